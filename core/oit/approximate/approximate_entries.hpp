#pragma once
// The approximate family's entries, one file per technique; approximateEntries() lists them.
#include "oit/technique.hpp"

namespace strata::approximate {

TechniqueEntry wboitEntry();       // wboit.cpp
TechniqueEntry stochasticEntry();  // stochastic.cpp
TechniqueEntry floorEntry();       // floor.cpp

}  // namespace strata::approximate

#pragma once
// `dual`: dual depth peeling, see dual_peeling.cpp.
#include "oit/technique.hpp"

namespace strata::peeling {

TechniqueEntry dualEntry();

}  // namespace strata::peeling

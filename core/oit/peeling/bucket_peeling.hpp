#pragma once
// `bun`: uniform bucket peeling, see bucket_peeling.cpp.
#include "oit/technique.hpp"

namespace strata::peeling {

TechniqueEntry bunEntry();

}  // namespace strata::peeling

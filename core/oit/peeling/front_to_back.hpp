#pragma once
// Front-to-back depth peeling: `f2b` (peel + layer blend) and `f2b2` (depth pre-pass + EQUAL
// shading), see front_to_back.cpp.
#include "oit/technique.hpp"

namespace strata::peeling {

TechniqueEntry f2bEntry();
TechniqueEntry f2b2Entry();

}  // namespace strata::peeling

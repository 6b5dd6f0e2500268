#pragma once
#include "oit/technique.hpp"

namespace strata {

TechniqueEntry blendUnsortedEntry();
TechniqueEntry blendSortedEntry();

}  // namespace strata

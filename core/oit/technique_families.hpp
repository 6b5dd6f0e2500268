#pragma once
// Each family of techniques registers its entries in its own file, so the registry lists them
// without knowing their classes.
#include "oit/technique.hpp"

#include <vector>

namespace strata {

std::vector<TechniqueEntry> baselineEntries();     // oit/blend_techniques.cpp
std::vector<TechniqueEntry> peelingEntries();      // oit/peeling/
std::vector<TechniqueEntry> bufferEntries();       // oit/buffers/
std::vector<TechniqueEntry> approximateEntries();  // oit/approximate/

}  // namespace strata

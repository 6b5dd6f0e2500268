#include "oit/approximate/approximate_entries.hpp"
#include "oit/technique_families.hpp"

namespace strata {

std::vector<TechniqueEntry> approximateEntries() {
    return {approximate::wboitEntry(), approximate::stochasticEntry(), approximate::floorEntry()};
}

}  // namespace strata

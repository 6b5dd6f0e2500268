// The peeling family in display order (registered from oit/technique_registry.cpp).
#include "oit/peeling/bucket_peeling.hpp"
#include "oit/peeling/dual_peeling.hpp"
#include "oit/peeling/front_to_back.hpp"
#include "oit/technique_families.hpp"

namespace strata {

std::vector<TechniqueEntry> peelingEntries() {
    return {peeling::f2bEntry(), peeling::f2b2Entry(), peeling::dualEntry(), peeling::bunEntry()};
}

}  // namespace strata

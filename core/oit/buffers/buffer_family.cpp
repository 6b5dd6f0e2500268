#include "oit/buffers/buffer_entries.hpp"
#include "oit/technique_families.hpp"

namespace strata {

std::vector<TechniqueEntry> bufferEntries() { return {kbufferEntry(), fabEntry(), llEntry(), sbufferEntry()}; }

}  // namespace strata

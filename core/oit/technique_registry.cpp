#include "oit/technique.hpp"

#include <stdexcept>

namespace strata {

#define STRATA_TECHNIQUE(entry) TechniqueEntry entry();
#include "oit/technique_list.inc"
#undef STRATA_TECHNIQUE

const std::vector<TechniqueEntry>& techniqueRegistry() {
    // An explicit list (not static self-registration, which a static library's linker drops).
    static const std::vector<TechniqueEntry> registry = {
#define STRATA_TECHNIQUE(entry) entry(),
#include "oit/technique_list.inc"
#undef STRATA_TECHNIQUE
    };
    return registry;
}

const TechniqueEntry* findTechnique(const std::string& id) {
    for (const auto& e : techniqueRegistry())
        if (e.info.id == id) return &e;
    return nullptr;
}

std::unique_ptr<Technique> createTechnique(const std::string& id) {
    if (const auto* e = findTechnique(id)) return e->create();
    std::string known;
    for (const auto& e : techniqueRegistry()) known += (known.empty() ? "" : ", ") + e.info.id;
    throw std::invalid_argument("unknown technique '" + id + "' (known: " + known + ")");
}

}  // namespace strata

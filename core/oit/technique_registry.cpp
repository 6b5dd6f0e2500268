#include "oit/abuffer.hpp"
#include "oit/technique.hpp"
#include "oit/technique_families.hpp"

#include <stdexcept>

namespace strata {

const std::vector<TechniqueEntry>& techniqueRegistry() {
    // Explicit list (not static self-registration, which a static library's linker drops).
    // Each family adds one line here (see technique_families.hpp).
    static const std::vector<TechniqueEntry> registry = [] {
        std::vector<TechniqueEntry> all;
        auto add = [&all](std::vector<TechniqueEntry> family) {
            for (auto& e : family) all.push_back(std::move(e));
        };
        add(baselineEntries());
        add(peelingEntries());
        add({abufferEntry()});
        add(bufferEntries());
        add(approximateEntries());
        return all;
    }();
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

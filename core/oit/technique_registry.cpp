#include "oit/abuffer.hpp"
#include "oit/technique.hpp"
#include "oit/technique_families.hpp"

#include <charconv>
#include <cmath>
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

void setParameter(Technique& technique, const std::string& assignment) {
    auto eq = assignment.find('=');
    if (eq == std::string::npos)
        throw std::invalid_argument("parameter '" + assignment + "' is not of the form name=value");
    std::string name = assignment.substr(0, eq);
    std::string text = assignment.substr(eq + 1);
    auto params = technique.parameters();
    for (auto& p : params) {
        if (p.name != name) continue;
        double value = 0;
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
            throw std::invalid_argument("parameter " + name + ": '" + text + "' is not a number");
        if (value < p.min || value > p.max || (p.integer && value != std::floor(value)))
            throw std::invalid_argument("parameter " + name + " = " + text + " outside [" + std::to_string(p.min) +
                                        ", " + std::to_string(p.max) + "]" + (p.integer ? " or not an integer" : ""));
        if (p.step > 0 && std::fmod(value - p.min, p.step) != 0.0)
            throw std::invalid_argument("parameter " + name + " = " + text + " is not " + std::to_string(p.min) +
                                        " plus a multiple of " + std::to_string(p.step));
        *p.value = value;
        return;
    }
    std::string known;
    for (auto& p : params) known += (known.empty() ? "" : ", ") + p.name;
    throw std::invalid_argument("technique " + technique.info().id + " has no parameter '" + name + "'" +
                                (known.empty() ? "" : " (has: " + known + ")"));
}

}  // namespace strata

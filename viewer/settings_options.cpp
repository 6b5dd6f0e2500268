#include "settings_options.hpp"

#include "oit/technique.hpp"

#include <sstream>
#include <stdexcept>

namespace strata {

void addSettingsOptions(CLI::App* command, SettingsArgs& args) {
    command->add_option("--set", args.set,
                        "technique setting [id.]name=value (repeatable; `strata modes --settings` lists them)");
    command->add_option("--settings", args.preset,
                        "JSON preset of technique settings: {\"[id.]name\": value, ...}, applied before --set");
}

std::vector<SettingAssignment> settingsAssignments(const SettingsArgs& args) {
    std::vector<SettingAssignment> assignments;
    if (!args.preset.empty()) assignments = readSettingsPreset(args.preset);
    for (auto& a : commandLineAssignments(args.set)) assignments.push_back(std::move(a));
    return assignments;
}

std::vector<std::string> allTechniqueIds() {
    std::vector<std::string> ids;
    for (const auto& e : techniqueRegistry()) ids.push_back(e.info.id);
    return ids;
}

std::vector<std::string> parseModeList(const std::string& text) {
    std::vector<std::string> out;
    if (text == "all") return out;
    std::stringstream in(text);
    std::string id;
    while (std::getline(in, id, ','))
        if (!id.empty()) out.push_back(id);
    if (out.empty()) throw std::invalid_argument("--modes '" + text + "' names no technique");
    return out;
}

}  // namespace strata

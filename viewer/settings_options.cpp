#include "settings_options.hpp"

#include "oit/technique.hpp"

namespace strata {

void addSettingsOptions(CLI::App* command, SettingsArgs& args) {
    command->add_option("--set", args.set,
                        "technique setting [id.]name=value (repeatable; `strata modes --settings` lists them)");
    command->add_option("--settings", args.preset,
                        "JSON preset of technique settings: {\"[id.]name\": value, ...}, applied before --set");
}

SettingsById resolveSettingsArgs(const std::vector<std::string>& ids, const SettingsArgs& args,
                                 const std::vector<SettingAssignment>& extra) {
    std::vector<SettingAssignment> assignments;
    if (!args.preset.empty()) assignments = readSettingsPreset(args.preset);
    for (auto& a : commandLineAssignments(args.set)) assignments.push_back(std::move(a));
    assignments.insert(assignments.end(), extra.begin(), extra.end());
    return resolveSettings(ids, assignments);
}

std::vector<std::string> allTechniqueIds() {
    std::vector<std::string> ids;
    for (const auto& e : techniqueRegistry()) ids.push_back(e.info.id);
    return ids;
}

}  // namespace strata

#pragma once
// `--set [id.]name=value` and `--settings FILE.json`, the same two options on every command that
// renders. The preset's assignments come first, so `--set` overrides it.
#include "oit/technique_settings.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace strata {

struct SettingsArgs {
    std::vector<std::string> set;
    std::string preset;
};

void addSettingsOptions(CLI::App* command, SettingsArgs& args);

// The options' assignments in the order they apply: the preset's, then --set's. Throws
// std::invalid_argument (one line) when the preset cannot be read. Resolve them with
// resolveSettings before a context exists (a bad one fails early), and again with
// resolveSettingsForDevice (oit/device_defaults.hpp) once the device is known.
std::vector<SettingAssignment> settingsAssignments(const SettingsArgs& args);

// Every registered technique: the set a command that can switch techniques resolves against.
std::vector<std::string> allTechniqueIds();

// `--modes`: "all" (empty: every technique) or ids separated by commas; throws
// std::invalid_argument when it names none. The ids themselves are checked by the command.
std::vector<std::string> parseModeList(const std::string& text);

}  // namespace strata

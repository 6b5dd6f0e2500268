#pragma once
// The one path from user input to technique settings. `render`, `bench`, `view`, immersive mode
// and JSON presets turn their `[id.]name=value` assignments into values here, before any frame is
// rendered, so a typo or an out-of-range value stops the command with one line instead of being
// ignored or noticed halfway through a bench.
#include "oit/settings.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace strata {

class Technique;

struct SettingAssignment {
    std::string text;    // "[id.]name=value"
    std::string origin;  // where it came from, for the error: "--set", a preset file's path
};

// Settings of the techniques a command may run, by technique id.
using SettingsById = std::map<std::string, SettingValues>;

// Starts from the defaults of every technique in `ids` and applies the assignments in order.
// `id.name=value` must name a technique in `ids` and one of its settings; `name=value` applies to
// every technique in `ids` that has the setting and must match at least one. Throws
// std::invalid_argument with one line naming the origin, the assignment and what is wrong.
SettingsById resolveSettings(const std::vector<std::string>& ids, const std::vector<SettingAssignment>& assignments);

// Applies assignments to one technique's current values (each must concern it), all or none.
void applySettings(Technique& technique, const std::vector<SettingAssignment>& assignments);

// `--set` values as assignments.
std::vector<SettingAssignment> commandLineAssignments(const std::vector<std::string>& texts);

// A JSON preset file: an object of "[id.]name" to a number or a boolean, e.g.
// {"ll.capacity": 16, "precision": 16}; its assignments in file order. Throws
// std::invalid_argument naming the file when it cannot be read or is not of that form.
std::vector<SettingAssignment> readSettingsPreset(const std::string& path);

// Creates technique `id` with its resolved settings (its defaults when `settings` lacks it).
std::unique_ptr<Technique> createConfiguredTechnique(const std::string& id, const SettingsById& settings);

// "capacity=16 tail=false precision=32": a technique's values for logs and reports.
std::string formatSettings(const std::vector<SettingDescription>& descriptions, const SettingValues& values);

}  // namespace strata

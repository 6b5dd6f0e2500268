#pragma once
// ImGui widgets for a technique's settings, one per description: a checkbox for a flag, a choice
// for a setting with allowed values, an integer or a real field clamped to the range.
#include "oit/settings.hpp"

namespace strata {

// Edits `values` (a copy the viewer applies between frames); returns true when one changed.
bool drawSettings(const std::vector<SettingDescription>& descriptions, SettingValues& values);

}  // namespace strata

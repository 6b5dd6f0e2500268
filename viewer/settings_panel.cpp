#include "settings_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace strata {
namespace {

std::string tooltip(const SettingDescription& d) {
    std::string text = d.help + "\n" + describeRange(d) + ", default " + formatSettingValue(d, d.defaultValue);
    if (d.change != SettingChange::Nothing) text += std::string("\na change makes the next frame ") + toString(d.change);
    return text;
}

bool drawOne(const SettingDescription& d, double& value) {
    bool changed = false;
    if (d.type == SettingType::Flag) {
        bool on = value != 0;
        if ((changed = ImGui::Checkbox(d.name.c_str(), &on))) value = on ? 1 : 0;
    } else if (!d.allowed.empty()) {
        const std::string preview = formatSettingValue(d, value);
        if (ImGui::BeginCombo(d.name.c_str(), preview.c_str())) {
            for (double option : d.allowed) {
                if (ImGui::Selectable(formatSettingValue(d, option).c_str(), option == value) && option != value) {
                    value = option;
                    changed = true;
                }
            }
            ImGui::EndCombo();
        }
    } else if (d.type == SettingType::Integer) {
        std::int64_t v = std::int64_t(value);
        const std::int64_t step = 1, stepFast = 16;
        if (ImGui::InputScalar(d.name.c_str(), ImGuiDataType_S64, &v, &step, &stepFast)) {
            value = std::clamp(double(v), d.min, d.max);
            changed = true;
        }
    } else {
        double v = value;
        const double range = d.max - d.min;
        const float speed = range > 0.0 && range < 1e9 ? float(range / 500.0) : float(std::max(std::abs(v), 1.0) * 0.01);
        if (ImGui::DragScalar(d.name.c_str(), ImGuiDataType_Double, &v, speed, &d.min, &d.max, "%.4g",
                              ImGuiSliderFlags_AlwaysClamp)) {
            value = std::clamp(v, d.min, d.max);
            changed = true;
        }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(d).c_str());
    return changed;
}

}  // namespace

bool drawSettings(const std::vector<SettingDescription>& descriptions, SettingValues& values) {
    if (descriptions.empty()) {
        ImGui::TextDisabled("no settings");
        return false;
    }
    values.resize(descriptions.size());
    bool changed = false;
    for (std::size_t i = 0; i < descriptions.size(); ++i) {
        ImGui::PushID(int(i));
        changed = drawOne(descriptions[i], values[i]) || changed;
        ImGui::PopID();
    }
    return changed;
}

}  // namespace strata

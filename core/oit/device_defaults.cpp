#include "oit/device_defaults.hpp"

#include <algorithm>

namespace strata {

std::vector<SettingAssignment> deviceDefaultSettings(const std::vector<std::string>& ids, const gl::DeviceInfo& device) {
    std::vector<SettingAssignment> out;
    auto has = [&ids](const char* id) { return std::find(ids.begin(), ids.end(), id) != ids.end(); };
    if (device.software()) {
        const std::string origin = "the default on a software renderer (" + device.renderer + ")";
        if (has("wboit")) out.push_back({"wboit.precision=32", origin});
        return out;
    }
    const std::string origin = "the default on a hardware renderer (" + device.renderer + ")";
    if (has("dual")) out.push_back({"dual.atomic_range=1", origin});
    return out;
}

SettingsById resolveSettingsForDevice(const std::vector<std::string>& ids, const std::vector<SettingAssignment>& assignments,
                                      const gl::DeviceInfo& device) {
    std::vector<SettingAssignment> all = deviceDefaultSettings(ids, device);
    all.insert(all.end(), assignments.begin(), assignments.end());
    return resolveSettings(ids, all);
}

}  // namespace strata

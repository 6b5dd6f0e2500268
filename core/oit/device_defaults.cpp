#include "oit/device_defaults.hpp"

#include <algorithm>

namespace strata {

std::vector<SettingAssignment> deviceDefaultSettings(const std::vector<std::string>& ids, const gl::DeviceInfo& device) {
    std::vector<SettingAssignment> out;
    if (device.software()) return out;
    const std::string origin = "the default on a hardware renderer (" + device.renderer + ")";
    if (std::find(ids.begin(), ids.end(), "dual") != ids.end()) out.push_back({"dual.atomic_range=1", origin});
    return out;
}

SettingsById resolveSettingsForDevice(const std::vector<std::string>& ids, const std::vector<SettingAssignment>& assignments,
                                      const gl::DeviceInfo& device) {
    std::vector<SettingAssignment> all = deviceDefaultSettings(ids, device);
    all.insert(all.end(), assignments.begin(), assignments.end());
    return resolveSettings(ids, all);
}

}  // namespace strata

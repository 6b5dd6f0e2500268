#pragma once
// Settings whose faster value depends on the device, each measured on both backends. They are
// applied before the user's assignments (--settings, --set), which override them, and only once
// a context exists, since the device decides them.
#include "gl/context.hpp"
#include "oit/technique_settings.hpp"

#include <string>
#include <vector>

namespace strata {

// The device's defaults for the techniques `ids` (those not in `ids` are left out, so the result
// resolves against them). Today two:
//  - dual.atomic_range=1 on a hardware renderer. On an H200 it made dual 1.4-4x faster at 8-32
//    layers, and 2.1-5.1x at precision 32 (docs/gpu-h200-session8.md). On llvmpipe, whose atomics
//    run one lane at a time, it is 2.4x slower (docs/gpu-h200-session5.md), so the struct's
//    default stays off.
//  - wboit.precision=32 on a software renderer, which converts half floats in software: on
//    llvmpipe wboit took 4.19-4.63 ms at 32 against 5.10-5.47 at 16 (builtin:layers:16, 256x256,
//    four alternating rounds, docs/results.md), and 32 needs no weight scaling either. A GPU writes
//    half floats at half the bandwidth, so the struct's default stays 16.
std::vector<SettingAssignment> deviceDefaultSettings(const std::vector<std::string>& ids, const gl::DeviceInfo& device);

// resolveSettings(ids, the device's defaults, then `assignments`).
SettingsById resolveSettingsForDevice(const std::vector<std::string>& ids, const std::vector<SettingAssignment>& assignments,
                                      const gl::DeviceInfo& device);

}  // namespace strata

#pragma once
// The settings every screen-door technique shares, described once: the supersampling factor,
// the side of the random masks and the seed they are drawn from.
#include "oit/settings.hpp"

namespace strata::screendoor {

// n of the n x n supersampling: a power of two, so the box filter is exact 2x2 averages.
template <class S>
typename SettingsSchema<S>::Field supersamplingSetting(int S::*member) {
    return memberAccess<S>({"supersampling", SettingType::Integer, 1, 16, {1, 2, 4, 8, 16}, 0, SettingChange::Reallocate,
                            "n of the n x n supersampling, box-filtered down by repeated 2x2 averaging (paper: 16)"},
                           member);
}

template <class S>
typename SettingsSchema<S>::Field maskSizeSetting(int S::*member) {
    return memberAccess<S>({"mask_size", SettingType::Integer, 16, 512, {16, 32, 64, 128, 256, 512}, 0,
                            SettingChange::Reallocate,
                            "side of each alpha level's random mask in texels (memory: side^2 * 256 B)"},
                           member);
}

template <class S>
typename SettingsSchema<S>::Field seedSetting(int S::*member) {
    return integerSetting(member, "seed", 0, 1 << 30, SettingChange::Reallocate,
                          "seed of the random masks and offsets: the same seed gives the same image bit for bit");
}

// The settings of the two mask techniques (image and object space): one struct for both.
struct MaskSettings {
    int supersampling = 4;
    int mask_size = 128;
    int seed = 1;
    static const SettingsSchema<MaskSettings>& schema() {
        static const SettingsSchema<MaskSettings> s{
            supersamplingSetting(&MaskSettings::supersampling),
            maskSizeSetting(&MaskSettings::mask_size),
            seedSetting(&MaskSettings::seed),
        };
        return s;
    }
};

}  // namespace strata::screendoor

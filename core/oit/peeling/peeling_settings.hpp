#pragma once
// The settings f2b, f2b2 and dual share: the same loop bound, the same object skipping and the
// same float targets, so they are described once.
#include "oit/settings.hpp"

namespace strata::peeling {

struct PeelingSettings {
    int maxPasses = 1024;
    bool skipPeeled = true;
    int precision = 32;
    bool readAhead = true;

    static const SettingsSchema<PeelingSettings>& schema() {
        static const SettingsSchema<PeelingSettings> s{
            integerSetting(&PeelingSettings::maxPasses, "max_passes", 1, 1000000, SettingChange::Nothing,
                           "most peel passes per frame (dual peels two layers a pass); a safety bound, hitting it "
                           "counts as overflow"),
            flagSetting(&PeelingSettings::skipPeeled, "skip_peeled", SettingChange::Nothing,
                        "skip objects whose bounds lie wholly on the peeled side of the last pass's depth "
                        "(section 3.3), found by occlusion queries"),
            precisionSetting(&PeelingSettings::precision, "peeled layers and accumulations (depths stay 32-bit)"),
            flagSetting(&PeelingSettings::readAhead, "read_ahead", SettingChange::Nothing,
                        "issue the next passes before the last pass's count is read, while the counts read prove "
                        "that fragments remain (a pass takes at most one a pixel, dual two), so the GPU does not "
                        "wait for the CPU between passes (f2b, f2b2, dual)"),
        };
        return s;
    }
};

}  // namespace strata::peeling

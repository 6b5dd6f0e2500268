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

    // The fields of any struct built on these (S derives from PeelingSettings).
    template <class S>
    static std::vector<typename SettingsSchema<S>::Field> fields() {
        return {
            integerSetting<S>(&S::maxPasses, "max_passes", 1, 1000000, SettingChange::Nothing,
                              "most peel passes per frame (dual peels two layers a pass); a safety bound, hitting "
                              "it counts as overflow"),
            flagSetting<S>(&S::skipPeeled, "skip_peeled", SettingChange::Nothing,
                           "skip objects whose bounds lie wholly on the peeled side of the last pass's depth "
                           "(section 3.3), found by occlusion queries"),
            precisionSetting<S>(&S::precision, "peeled layers and accumulations (depths stay 32-bit)"),
            flagSetting<S>(&S::readAhead, "read_ahead", SettingChange::Nothing,
                           "issue the next passes before the last pass's count is read, while the counts read "
                           "prove that fragments remain (a pass takes at most one a pixel, dual two), so the GPU "
                           "does not wait for the CPU between passes (f2b, f2b2, dual)"),
        };
    }
    static const SettingsSchema<PeelingSettings>& schema() {
        static const SettingsSchema<PeelingSettings> s{fields<PeelingSettings>()};
        return s;
    }
};

// dual's: the peeling settings and how a pass finds the next range.
struct DualSettings : PeelingSettings {
    bool atomicRange = false;
    bool backDepthTest = true;

    static const SettingsSchema<DualSettings>& schema() {
        static const SettingsSchema<DualSettings> s{[] {
            auto f = fields<DualSettings>();
            f.push_back(flagSetting<DualSettings>(
                &DualSettings::atomicRange, "atomic_range", SettingChange::Recompile,
                "find the next range by image atomics (max and min of the depth bits) instead of MAX blending "
                "into an RG32F target; the fragments inside the range are then discarded, so only the two "
                "layers' reach the blending units, for a counting pass and a full-screen pass after the init "
                "and each peel: faster where blending is slow (an H200: 2.5-4.6x), slower where atomics are "
                "(llvmpipe: 2.4x)"));
            f.push_back(flagSetting<DualSettings>(
                &DualSettings::backDepthTest, "back_depth_test", SettingChange::Reallocate,
                "reject the fragments behind the range (the back layers peeled already, and all at a "
                "finished pixel) by the depth test, before they are shaded: the back of each range goes to "
                "a depth buffer, written by the blend (or atomic_range's pack); the first peel tests the opaque depth"));
            return f;
        }()};
        return s;
    }
};

}  // namespace strata::peeling

#pragma once
// Settings of the coplanarity-aware peeling variants that store each layer's coincident
// fragments (f2b-ll, dual-ll with linked lists; f2b-fab, f2b-kb, dual-fab with K per pixel),
// and the technique class they share: an engine (front-to-back or dual) run with them.
#include "oit/settings.hpp"
#include "oit/technique.hpp"

#include <string>

namespace strata::peeling {

struct LayerPeelingSettings {
    int maxPasses = 1024;
    bool skipPeeled = true;
    int precision = 32;
    int capacity = 8;         // bounded variants: K fragments of a layer per pixel (and side)
    double maxBlockMiB = 0;   // list variants: the largest node pool
};

namespace detail {
template <class S>
typename SettingsSchema<S>::Field maxPassesField() {
    return integerSetting<S>(&S::maxPasses, "max_passes", 1, 1000000, SettingChange::Nothing,
                             "most peel iterations per frame (dual peels two layers an iteration); a safety bound, "
                             "hitting it counts as overflow");
}
template <class S>
typename SettingsSchema<S>::Field skipPeeledField() {
    return flagSetting<S>(&S::skipPeeled, "skip_peeled", SettingChange::Nothing,
                          "skip objects whose bounds lie wholly on the peeled side of the last layer (section 3.3), "
                          "found by occlusion queries");
}
}  // namespace detail

// f2b-ll, dual-ll: the pool grows to each layer's fragments, so nothing has a capacity to pick.
struct LayerListSettings : LayerPeelingSettings {
    static const SettingsSchema<LayerListSettings>& schema() {
        using S = LayerListSettings;
        static const SettingsSchema<S> s{
            detail::maxPassesField<S>(),
            detail::skipPeeledField<S>(),
            precisionSetting<S>(&S::precision, "accumulations (depths stay 32-bit)"),
            realSetting<S>(&S::maxBlockMiB, "max_block_mib", 0, 1e6, SettingChange::Reallocate,
                           "largest node pool in MiB (0: the device's GL_MAX_SHADER_STORAGE_BLOCK_SIZE); a layer "
                           "with more fragments keeps what fits and counts the rest as overflow"),
        };
        return s;
    }
};

// f2b-fab, f2b-kb, dual-fab: K coincident fragments per pixel and layer.
struct LayerBufferSettings : LayerPeelingSettings {
    static const SettingsSchema<LayerBufferSettings>& schema() {
        using S = LayerBufferSettings;
        static const SettingsSchema<S> s{
            integerSetting<S>(&S::capacity, "capacity", 1, 64, SettingChange::Reallocate,
                              "coincident fragments kept per pixel and layer (K): the first K to arrive; the rest of "
                              "the layer is counted as overflow"),
            detail::maxPassesField<S>(),
            detail::skipPeeledField<S>(),
            precisionSetting<S>(&S::precision, "accumulations (depths stay 32-bit)"),
        };
        return s;
    }
};

// A technique whose frame is `Engine::render(frame, settings, stats)`; Engine is built from the
// technique's id and `args`.
template <class S, class Engine>
class LayerPeelingTechnique final : public TechniqueWithSettings<S> {
public:
    template <class... Args>
    LayerPeelingTechnique(TechniqueInfo info, Args... args)
        : TechniqueWithSettings<S>(std::move(info)), engine_(this->info_.id, args...) {}
    void render(const FrameContext& frame) override { engine_.render(frame, this->settings_, this->stats_); }

private:
    Engine engine_;
};

}  // namespace strata::peeling

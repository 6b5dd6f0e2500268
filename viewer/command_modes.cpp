// `strata modes`: the technique registry as a table.
#include "commands.hpp"

#include "oit/technique.hpp"

#include "io/parse_integers.hpp"
#include "io/printable.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace strata {

glm::ivec2 parseSize(const std::string& text) {
    const auto wh = parseIntPair(text, "xX");
    if (!wh || wh->first < 1 || wh->second < 1 || wh->first > 16384 || wh->second > 16384)
        throw std::invalid_argument("size '" + printable(text, 40) + "' is not WxH with 1 <= W, H <= 16384");
    return {wh->first, wh->second};
}

void registerModesCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "modes", "list the transparency techniques: id, family, robust?, coplanarity?, coloured filters, passes, memory");
    auto withSettings = std::make_shared<bool>(false);
    cmd->add_flag("--settings", *withSettings,
                  "under each technique, its settings: name, range, default, what a change forces, help");
    cmd->callback([withSettings] {
        std::printf("%-16s %-11s %-7s %-10s %-8s %-34s %s\n", "id", "family", "robust", "coplanar", "filters", "passes",
                    "memory");
        for (const auto& e : techniqueRegistry()) {
            const auto& i = e.info;
            std::printf("%-16s %-11s %-7s %-10s %-8s %-34s %s\n", i.id.c_str(), i.family.c_str(), i.robust ? "yes" : "no",
                        i.handlesCoplanarity ? "yes" : "no", i.rgbTransmittance ? "rgb" : "scalar", i.passes.c_str(),
                        i.memoryModel.c_str());
            if (!*withSettings) continue;
            for (const auto& d : e.settings)
                std::printf("    %-20s %-24s default %-6s change: %-10s %s\n", d.name.c_str(), describeRange(d).c_str(),
                            formatSettingValue(d, d.defaultValue).c_str(), toString(d.change), d.help.c_str());
        }
        std::printf("\nfilters: how a transmissive (KHR_materials_transmission) surface composites. rgb: its "
                    "transmittance per channel (glass behind coloured glass keeps both tints; exact where the technique's "
                    "order is). scalar: one "
                    "alpha, 1 - mean transmittance, with the colour premultiplied over it: brightness kept, tint lost.\n");
    });
}

}  // namespace strata

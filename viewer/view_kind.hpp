#pragma once
// What the viewer's window shows: the technique's image, or the coplanarity heatmap of the same
// frame (oit/coplanarity_detector.hpp). Named once for the panel and `strata view --view`.
#include <array>
#include <optional>
#include <string>

namespace strata {

enum class ViewKind { Image, CoplanarityHeatmap };

inline constexpr std::array<ViewKind, 2> kViewKinds{ViewKind::Image, ViewKind::CoplanarityHeatmap};

// The command-line name: "image", "heatmap".
inline const char* viewName(ViewKind v) { return v == ViewKind::Image ? "image" : "heatmap"; }

// The panel's label.
inline const char* viewLabel(ViewKind v) { return v == ViewKind::Image ? "image" : "coplanarity heatmap"; }

inline std::optional<ViewKind> parseView(const std::string& name) {
    for (ViewKind v : kViewKinds)
        if (name == viewName(v)) return v;
    return std::nullopt;
}

}  // namespace strata

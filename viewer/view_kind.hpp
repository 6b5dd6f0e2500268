#pragma once
// What the viewer's window shows: the technique's image, the coplanarity heatmap of the same
// frame (oit/coplanarity_detector.hpp), the error against the reference (`abuffer` on the same
// frame, render/error_map.hpp), or two techniques split A | B. Named once for the panel and
// `strata view --view`.
#include <array>
#include <optional>
#include <string>

namespace strata {

enum class ViewKind { Image, CoplanarityHeatmap, Error, Split };

inline constexpr std::array<ViewKind, 4> kViewKinds{ViewKind::Image, ViewKind::CoplanarityHeatmap, ViewKind::Error,
                                                    ViewKind::Split};

// The command-line name: "image", "heatmap", "error", "split".
inline const char* viewName(ViewKind v) {
    switch (v) {
    case ViewKind::Image: return "image";
    case ViewKind::CoplanarityHeatmap: return "heatmap";
    case ViewKind::Error: return "error";
    case ViewKind::Split: return "split";
    }
    return "image";
}

// The panel's label.
inline const char* viewLabel(ViewKind v) {
    switch (v) {
    case ViewKind::Image: return "image";
    case ViewKind::CoplanarityHeatmap: return "coplanarity heatmap";
    case ViewKind::Error: return "error";
    case ViewKind::Split: return "split A | B";
    }
    return "image";
}

inline std::optional<ViewKind> parseView(const std::string& name) {
    for (ViewKind v : kViewKinds)
        if (name == viewName(v)) return v;
    return std::nullopt;
}

}  // namespace strata

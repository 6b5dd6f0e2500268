#pragma once
// Coplanarity as the heatmap shows it (Vasilakis and Fudos, section 3 and Fig. 13): for each pixel,
// the largest number of transparent fragments that share one depth layer under the exact
// reference's tie rule (render/depth_order.hpp). The GPU detector (oit/coplanarity_detector.hpp)
// and the CPU ray cast both reduce a pixel to this number; the palette, the statistics and the
// CPU rule live here so the two are judged by one definition. No GL.
#include "image/image.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace strata {

// Histogram bins of the largest layer: bin 0 no fragment, bin k a largest layer of k fragments,
// the last bin kCoplanarityBins - 1 or more (Fig. 13's "brown = 9").
inline constexpr int kCoplanarityBins = 10;

// Fig. 13's colour (common/coplanarity_palette.h) in linear RGB: grey for 0 or 1 fragment per
// layer, then red 2, blue 3, green 4, cyan 5, aquamarine 6, fuchsia 7, yellow 8, brown 9 or more.
glm::vec3 coplanarityColor(int largestLayer);

// The palette's names in the same order, for legends ("grey", "red", ...).
const char* coplanarityColorName(int largestLayer);

struct CoplanarityStats {
    std::array<std::uint64_t, kCoplanarityBins> pixelsByLargestLayer{};
    std::uint64_t fragments = 0;  // transparent fragments in front of the opaque depth
    std::uint64_t layers = 0;     // depth layers summed over the pixels

    std::uint64_t pixels() const;
    std::uint64_t pixelsWithFragments() const;  // bins 1 and up
    std::uint64_t pixelsWithTies() const;       // bins 2 and up: a layer of two or more

    // C_p, "the average probability for a pixel to suffer from fragment coplanarity when
    // rendering with F2B": the share of pixels with fragments whose fragments share a layer
    // (0 when nothing is transparent). The same quantity as ReferenceStats::coplanarityProbability.
    double coplanarityProbability() const;

    // R_h of any technique that keeps one fragment per depth layer (F2B, DUAL, BUN without the
    // paper's extensions): layers / fragments, 1 when nothing is transparent. Robust
    // coplanarity-aware techniques have R_h = 1 whatever this is.
    double oneFragmentPerLayerRobustness() const;

    // Adds one pixel's figures.
    void add(int largestLayer, int layerCount, int fragmentCount);
};

// The CPU rule, on one pixel's eye depths (any order): sorted, cut into layers where
// neighbours differ by more than `tolerance` relative (render/depth_order.hpp's sameDepthLayer),
// and the largest layer's size (0 for no depth). `layers`, when given, receives the layer count.
int largestDepthLayer(std::vector<float> eyeDepths, double tolerance, int* layers = nullptr);

// The heatmap image of a per-pixel largest-layer map (row 0 at the bottom, width * height values).
Image coplanarityHeatmap(const std::vector<std::uint32_t>& largestLayers, int width, int height);

// Coplanarity highlighted on the shaded image (the paper's Fig. 12 application: where a mesh
// intersects itself or another, or surfaces coincide): pixels whose largest layer holds two or
// more take `strength` of their Fig. 13 colour over the shaded colour; the rest stay as shaded.
// Throws std::invalid_argument when the sizes differ or strength is outside [0, 1].
Image coplanarityHighlight(const Image& shaded, const std::vector<std::uint32_t>& largestLayers,
                           float strength = 0.6f);

}  // namespace strata

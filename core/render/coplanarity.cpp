#include "render/coplanarity.hpp"

#include "common/coplanarity_palette.h"
#include "render/depth_order.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace strata {
namespace {

constexpr gpu::uint kPaletteSrgb[] = {COPLANARITY_PALETTE_SRGB};
static_assert(std::size(kPaletteSrgb) == gpu::COPLANARITY_PALETTE_SIZE);
// The histogram's last bin is the palette's last colour: "9 or more".
static_assert(kCoplanarityBins == int(gpu::COPLANARITY_PALETTE_SIZE) + 1);

constexpr const char* kPaletteNames[] = {"grey",       "red",     "blue",   "green", "cyan",
                                         "aquamarine", "fuchsia", "yellow", "brown"};
static_assert(std::size(kPaletteNames) == gpu::COPLANARITY_PALETTE_SIZE);

int paletteIndex(int largestLayer) { return std::clamp(largestLayer, 1, int(gpu::COPLANARITY_PALETTE_SIZE)) - 1; }

}  // namespace

glm::vec3 coplanarityColor(int largestLayer) {
    const gpu::uint c = kPaletteSrgb[paletteIndex(largestLayer)];
    auto channel = [&](int shift) { return srgbToLinear(float((c >> shift) & 0xFFu) / 255.0f); };
    return {channel(16), channel(8), channel(0)};
}

const char* coplanarityColorName(int largestLayer) { return kPaletteNames[paletteIndex(largestLayer)]; }

std::uint64_t CoplanarityStats::pixels() const {
    std::uint64_t n = 0;
    for (auto v : pixelsByLargestLayer) n += v;
    return n;
}

std::uint64_t CoplanarityStats::pixelsWithFragments() const { return pixels() - pixelsByLargestLayer[0]; }

std::uint64_t CoplanarityStats::pixelsWithTies() const { return pixelsWithFragments() - pixelsByLargestLayer[1]; }

double CoplanarityStats::coplanarityProbability() const {
    const std::uint64_t covered = pixelsWithFragments();
    return covered ? double(pixelsWithTies()) / double(covered) : 0.0;
}

double CoplanarityStats::oneFragmentPerLayerRobustness() const {
    return fragments ? double(layers) / double(fragments) : 1.0;
}

void CoplanarityStats::add(int largestLayer, int layerCount, int fragmentCount) {
    ++pixelsByLargestLayer[std::size_t(std::clamp(largestLayer, 0, kCoplanarityBins - 1))];
    layers += std::uint64_t(layerCount);
    fragments += std::uint64_t(fragmentCount);
}

int largestDepthLayer(std::vector<float> eyeDepths, double tolerance, int* layers) {
    std::sort(eyeDepths.begin(), eyeDepths.end());
    int largest = 0, run = 0, count = 0;
    for (std::size_t i = 0; i < eyeDepths.size(); ++i) {
        if (i > 0 && sameDepthLayer(eyeDepths[i - 1], eyeDepths[i], tolerance)) {
            ++run;
        } else {
            run = 1;
            ++count;
        }
        largest = std::max(largest, run);
    }
    if (layers) *layers = count;
    return largest;
}

Image coplanarityHeatmap(const std::vector<std::uint32_t>& largestLayers, int width, int height) {
    if (width < 0 || height < 0 || largestLayers.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("coplanarity heatmap: " + std::to_string(largestLayers.size()) +
                                    " values for a " + std::to_string(width) + "x" + std::to_string(height) +
                                    " image");
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t n = largestLayers[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            image.set(x, y, glm::vec4(coplanarityColor(int(std::min<std::uint32_t>(n, 1u << 30))), 1.0f));
        }
    return image;
}

Image coplanarityHighlight(const Image& shaded, const std::vector<std::uint32_t>& largestLayers, float strength) {
    if (largestLayers.size() != std::size_t(shaded.width) * std::size_t(shaded.height))
        throw std::invalid_argument("coplanarity highlight: " + std::to_string(largestLayers.size()) + " values for a " +
                                    std::to_string(shaded.width) + "x" + std::to_string(shaded.height) + " image");
    if (!(strength >= 0.0f && strength <= 1.0f))
        throw std::invalid_argument("coplanarity highlight: strength must lie in [0, 1]");
    Image out = shaded;
    for (int y = 0; y < shaded.height; ++y)
        for (int x = 0; x < shaded.width; ++x) {
            const std::uint32_t n = largestLayers[std::size_t(y) * std::size_t(shaded.width) + std::size_t(x)];
            if (n < 2) continue;
            const glm::vec4 c = shaded.at(x, y);
            const glm::vec3 tint = coplanarityColor(int(std::min<std::uint32_t>(n, 1u << 30)));
            out.set(x, y, glm::vec4(glm::mix(glm::vec3(c), tint, strength), c.a));
        }
    return out;
}

}  // namespace strata

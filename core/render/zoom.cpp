#include "render/zoom.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

namespace strata {

glm::ivec2 zoomRenderSize(glm::ivec2 displaySize, int zoom) {
    if (zoom < 1 || zoom > kMaxZoom)
        throw std::invalid_argument("zoom " + std::to_string(zoom) + " is outside 1.." + std::to_string(kMaxZoom));
    if (displaySize.x <= 0 || displaySize.y <= 0) throw std::invalid_argument("display size must be positive");
    return (displaySize + (zoom - 1)) / zoom;
}

glm::mat4 zoomProjection(const glm::mat4& displayProjection, glm::ivec2 displaySize, int zoom) {
    const glm::ivec2 reduced = zoomRenderSize(displaySize, zoom);
    if (zoom == 1) return displayProjection;
    // Applied to clip coordinates: x_c' = k x_c + (k - 1) w_c, which divides to the NDC map.
    const glm::vec2 k = glm::vec2(displaySize) / (float(zoom) * glm::vec2(reduced));
    glm::mat4 toReduced(1.0f);
    toReduced[0][0] = k.x;
    toReduced[1][1] = k.y;
    toReduced[3][0] = k.x - 1.0f;  // column 3 holds what multiplies w
    toReduced[3][1] = k.y - 1.0f;
    return toReduced * displayProjection;
}

int parseZoom(std::string_view text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > kMaxZoom)
        throw std::invalid_argument("zoom '" + std::string(text) + "' is not an integer in 1.." +
                                    std::to_string(kMaxZoom));
    return value;
}

}  // namespace strata

// `strata_screenshot_content FILE [MIN_SHARE]`: whether a screenshot shows content, for the
// browser test of the report page (tests/report_browser_test.sh). A blank or failed page is one
// colour (white, or Chromium's error page's few); the report is photographs, a chart and text.
// Prints the size, the number of distinct 8-bit colours and the share of pixels that differ from
// the top-left pixel (the page background); exits 1 when that share is below MIN_SHARE (default
// 0.05) or fewer than 256 colours appear, 2 when the file cannot be read.
#include "image/image.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <unordered_set>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: %s FILE [MIN_SHARE]\n", argv[0]);
        return 2;
    }
    const double minShare = argc == 3 ? std::atof(argv[2]) : 0.05;
    try {
        const strata::Image image = strata::readImage(argv[1]);
        std::unordered_set<std::uint32_t> colours;
        auto key = [&](int x, int y) {
            const glm::vec4 c = image.at(x, y);
            auto byte = [](float v) { return std::uint32_t(strata::linearToSrgb(v) * 255.0f + 0.5f) & 0xFFu; };
            return byte(c.r) << 16 | byte(c.g) << 8 | byte(c.b);
        };
        const std::uint32_t background = key(0, image.height - 1);  // row 0 is the bottom
        std::size_t differing = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const std::uint32_t k = key(x, y);
                colours.insert(k);
                differing += k != background;
            }
        const double share = image.width && image.height ? double(differing) / (double(image.width) * image.height) : 0.0;
        std::printf("%s: %dx%d, %zu colours, %.1f %% of pixels not the background\n", argv[1], image.width, image.height,
                    colours.size(), 100.0 * share);
        return share >= minShare && colours.size() >= 256 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
}

#pragma once
// A linear-RGB float image, bottom row first (OpenGL's convention), and what we do with it:
// write PNG (sRGB-encoded 8 bit) or EXR (linear half), read, and compare.
#include "io/atomic_file.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace strata {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // width * height * 4, row 0 = bottom

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * h * 4, 0.0f) {}
    glm::vec4 at(int x, int y) const {
        const float* p = &rgba[(std::size_t(y) * width + x) * 4];
        return {p[0], p[1], p[2], p[3]};
    }
    void set(int x, int y, const glm::vec4& v) {
        float* p = &rgba[(std::size_t(y) * width + x) * 4];
        p[0] = v.r; p[1] = v.g; p[2] = v.b; p[3] = v.a;
    }
};

struct ImageDifference {
    double rmse = 0.0;          // over RGB, linear
    double psnr = 0.0;          // dB, peak 1.0; capped at 100 for identical images
    double maxAbsError = 0.0;   // largest per-channel difference, RGB
    std::size_t pixelsOver = 0; // pixels whose max channel difference exceeds the threshold
};

// The image shrunk `factor` times each way, each pixel the mean of its factor x factor block (a
// supersampled frame's antialiased version). Throws unless both sides divide by the factor.
Image averageDown(const Image& image, int factor);

// Compares RGB (alpha ignored) through OpenImageIO. Throws if the sizes differ.
ImageDifference compareImages(const Image& a, const Image& b, float threshold = 1.0f / 255.0f);

// Error over a run of frames, fed one frame at a time and holding no image: the RMSE over every
// frame's RGB channels together (as if the frames were one image) and the largest difference of
// any channel in any frame. Frames may differ in size.
class ErrorAccumulator {
public:
    // Compares one frame (through compareImages) and adds it; returns that frame's difference.
    ImageDifference add(const Image& image, const Image& reference);
    // Adds a difference computed elsewhere over `channels` RGB values.
    void add(const ImageDifference& difference, std::size_t channels);

    double rmse() const;
    double psnr() const;          // dB, peak 1.0; 100 when nothing differs (as compareImages)
    double maxAbsError() const { return maxAbsError_; }
    std::size_t channels() const { return channels_; }

private:
    double sumSquares_ = 0.0;
    std::size_t channels_ = 0;
    double maxAbsError_ = 0.0;
};

// Writes .png (sRGB 8-bit) or .exr (linear half) through writeFileAtomically (io/atomic_file.hpp),
// so a failure leaves nothing half-written. Throws std::runtime_error naming the file.
void writeImage(const std::filesystem::path& path, const Image& image);
// The same as one output of `batch`: the file appears when the batch commits.
// Throws what writeImage would for `path` before any pixel exists: an unsupported extension, or
// what checkWritable (io/atomic_file.hpp) finds. Commands call it before rendering.
void checkImageWritable(const std::filesystem::path& path);
void writeImage(OutputBatch& batch, const std::filesystem::path& path, const Image& image);
Image readImage(const std::filesystem::path& path);  // .exr linear; .png decoded from sRGB

// `image` reduced by an integer `factor` (>= 1) with a box filter in linear RGB (alpha too); the
// last partial row and column average what they cover. For thumbnails.
Image boxDownscale(const Image& image, int factor);

float linearToSrgb(float v);
float srgbToLinear(float v);

}  // namespace strata

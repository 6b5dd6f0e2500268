#include "image/image.hpp"

#include "common/shading_model.h"
#include "io/atomic_file.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace strata {
namespace fs = std::filesystem;

float linearToSrgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

// The decode textures use too (common/shading_model.h), so a PNG read back and a texel agree.
float srgbToLinear(float v) { return gpu::srgbToLinear(v); }

namespace {

// OpenImageIO wants the top row first; our images keep GL's bottom row first.
OIIO::ImageBuf toImageBuf(const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buf(spec);
    std::vector<float> flipped(image.rgba.size());
    std::size_t row = std::size_t(image.width) * 4;
    for (int y = 0; y < image.height; ++y)
        std::copy_n(&image.rgba[std::size_t(image.height - 1 - y) * row], row, &flipped[std::size_t(y) * row]);
    buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, flipped.data());
    return buf;
}

}  // namespace

Image averageDown(const Image& image, int factor) {
    if (factor < 1 || image.width % factor != 0 || image.height % factor != 0)
        throw std::invalid_argument("averageDown: " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                    " does not divide by " + std::to_string(factor));
    Image out(image.width / factor, image.height / factor);
    const float weight = 1.0f / float(factor * factor);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            glm::vec4 sum(0.0f);
            for (int j = 0; j < factor; ++j)
                for (int i = 0; i < factor; ++i) sum += image.at(x * factor + i, y * factor + j);
            out.set(x, y, sum * weight);
        }
    return out;
}

ImageDifference compareImages(const Image& a, const Image& b, float threshold) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("compareImages: sizes differ (" + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                    std::to_string(b.height) + ")");
    OIIO::ImageBuf A = toImageBuf(a), B = toImageBuf(b);
    OIIO::ROI rgb = OIIO::get_roi(A.spec());
    rgb.chbegin = 0;
    rgb.chend = 3;
    auto r = OIIO::ImageBufAlgo::compare(A, B, threshold, threshold, rgb);
    ImageDifference d;
    d.rmse = r.rms_error;
    d.maxAbsError = r.maxerror;
    d.pixelsOver = std::size_t(r.nfail);
    d.psnr = d.rmse > 0.0 ? std::min(100.0, 20.0 * std::log10(1.0 / d.rmse)) : 100.0;
    return d;
}

ImageDifference ErrorAccumulator::add(const Image& image, const Image& reference) {
    ImageDifference d = compareImages(image, reference);
    add(d, std::size_t(image.width) * std::size_t(image.height) * 3);
    return d;
}

void ErrorAccumulator::add(const ImageDifference& difference, std::size_t channels) {
    // compareImages's rmse is sqrt(sum of squares / channels): undo the mean to sum over frames.
    sumSquares_ += difference.rmse * difference.rmse * double(channels);
    channels_ += channels;
    maxAbsError_ = std::max(maxAbsError_, difference.maxAbsError);
}

double ErrorAccumulator::rmse() const {
    return channels_ ? std::sqrt(sumSquares_ / double(channels_)) : 0.0;
}

double ErrorAccumulator::psnr() const {
    double e = rmse();
    return e > 0.0 ? std::min(100.0, 20.0 * std::log10(1.0 / e)) : 100.0;
}

namespace {

void checkImageType(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext != ".png" && ext != ".exr")
        throw std::runtime_error(path.string() + ": unsupported image type (use .png or .exr)");
}

}  // namespace

void checkImageWritable(const fs::path& path) {
    checkWritable(path);
    checkImageType(path);
}

void writeImage(const fs::path& path, const Image& image) {
    OutputBatch batch;
    writeImage(batch, path, image);
    batch.commit();
}

void writeImage(OutputBatch& batch, const fs::path& path, const Image& image) {
    checkImageType(path);
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (image.width <= 0 || image.height <= 0) throw std::runtime_error(path.string() + ": empty image");

    // Top row first for the file; PNG holds sRGB-encoded 8-bit colour, EXR linear half floats.
    const std::size_t row = std::size_t(image.width) * 4;
    std::vector<float> pixels(image.rgba.size());
    for (int y = 0; y < image.height; ++y)
        std::copy_n(&image.rgba[std::size_t(image.height - 1 - y) * row], row, &pixels[std::size_t(y) * row]);
    bool png = ext == ".png";
    std::vector<unsigned char> bytes;
    if (png) {
        bytes.resize(pixels.size());
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            float v = (i % 4 == 3) ? std::clamp(pixels[i], 0.0f, 1.0f) : linearToSrgb(pixels[i]);
            bytes[i] = static_cast<unsigned char>(std::lround(v * 255.0f));
        }
    }

    batch.add(path, [&](const fs::path& temporary) {
        auto fail = [](const std::string& why) { throw std::runtime_error("cannot write image: " + why); };
        auto out = OIIO::ImageOutput::create(temporary.string());
        if (!out) fail(OIIO::geterror());
        OIIO::ImageSpec spec(image.width, image.height, 4, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::HALF);
        spec.attribute("oiio:ColorSpace", png ? "sRGB" : "Linear");
        if (!out->open(temporary.string(), spec)) fail(out->geterror());
        bool ok = png ? out->write_image(OIIO::TypeDesc::UINT8, bytes.data())
                      : out->write_image(OIIO::TypeDesc::FLOAT, pixels.data());
        if (!ok) fail(out->geterror());
        if (!out->close()) fail(out->geterror());
        // OpenEXR's writer can report success although its last write failed (a full disk, a
        // file-size limit: seen truncated at the limit with every call returning true), so the
        // file is read back whole before it may take the destination's name.
        auto in = OIIO::ImageInput::open(temporary.string());
        std::vector<float> check(pixels.size());
        if (!in || !in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, check.data()))
            fail("the written file does not read back: " + (in ? in->geterror() : OIIO::geterror()));
    });
}

Image readImage(const fs::path& path) {
    OIIO::ImageBuf buf(path.string());
    if (!buf.read(0, 0, true, OIIO::TypeDesc::FLOAT))
        throw std::runtime_error(path.string() + ": cannot read image: " + buf.geterror());
    const auto& spec = buf.spec();
    Image image(spec.width, spec.height);
    bool srgb = path.extension() == ".png";
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x) {
            float px[4] = {0, 0, 0, 1};
            buf.getpixel(x, y, px, std::min(4, spec.nchannels));
            if (spec.nchannels < 4) px[3] = 1.0f;
            if (srgb) for (int c = 0; c < 3; ++c) px[c] = srgbToLinear(px[c]);
            image.set(x, spec.height - 1 - y, {px[0], px[1], px[2], px[3]});
        }
    return image;
}

Image boxDownscale(const Image& image, int factor) {
    if (factor < 1) throw std::invalid_argument("boxDownscale: factor must be at least 1");
    const int w = (image.width + factor - 1) / factor, h = (image.height + factor - 1) / factor;
    Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec4 sum(0.0f);
            int n = 0;
            for (int sy = y * factor; sy < std::min(image.height, (y + 1) * factor); ++sy)
                for (int sx = x * factor; sx < std::min(image.width, (x + 1) * factor); ++sx, ++n) sum += image.at(sx, sy);
            out.set(x, y, sum / float(n));
        }
    return out;
}

}  // namespace strata

#include "scene/image_decode.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstring>
#include <new>

namespace strata {
namespace {

// The format from the magic bytes: OpenImageIO picks its reader by the file name's extension,
// and an image in a buffer has none (a data URI's or a bufferView's mimeType may lie).
const char* formatName(const unsigned char* b, std::size_t n) {
    if (n >= 8 && std::memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0) return "image.png";
    if (n >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return "image.jpg";
    if (n >= 12 && std::memcmp(b, "RIFF", 4) == 0 && std::memcmp(b + 8, "WEBP", 4) == 0) return "image.webp";
    return nullptr;
}

bool isKtx2(const unsigned char* b, std::size_t n) {
    static const unsigned char magic[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
    return n >= 12 && std::memcmp(b, magic, 12) == 0;
}

}  // namespace

bool decodeImage(const unsigned char* bytes, std::size_t size, TextureImage& out, std::string& error) {
    if (isKtx2(bytes, size)) {
        error = "KTX2 (KHR_texture_basisu) is not supported: Debian has no KTX2 decoder library";
        return false;
    }
    const char* name = formatName(bytes, size);
    if (!name) {
        error = "not a PNG, JPEG or WebP image";
        return false;
    }
    OIIO::Filesystem::IOMemReader memory(bytes, size);
    // glTF alpha is straight (unassociated): ask the reader not to premultiply colour by it.
    // With a configuration, the proxy is passed in it (OIIO 2.4 takes the argument only without one).
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::Filesystem::IOProxy* proxy = &memory;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto input = OIIO::ImageInput::open(name, &config, &memory);
    if (!input) {
        std::string why = OIIO::geterror();
        error = "cannot decode (" + (why.empty() ? std::string("no reader for it") : why.substr(0, 120)) + ")";
        return false;
    }
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide || spec.height > kMaxImageSide) {
        error = std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is outside 1.." +
                std::to_string(kMaxImageSide) + " a side";
        return false;
    }
    const std::size_t decoded = std::size_t(spec.width) * std::size_t(spec.height) * 4;
    if (decoded > kMaxImageBytes) {
        error = std::to_string(spec.width) + "x" + std::to_string(spec.height) + " decodes to more than " +
                std::to_string(kMaxImageBytes >> 20) + " MiB";
        return false;
    }
    const int channels = spec.nchannels;
    if (channels < 1 || channels > 4) {
        error = std::to_string(channels) + " channels (1 to 4 expected)";
        return false;
    }
    std::vector<std::uint8_t> pixels;
    try {
        pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
    } catch (const std::bad_alloc&) {
        error = "out of memory for its pixels";
        return false;
    }
    // 16-bit and float images are converted to 8 bits by the reader.
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
        std::string why = input->geterror();
        error = "cannot decode (" + (why.empty() ? std::string("read failed") : why.substr(0, 120)) + ")";
        return false;
    }
    out.width = spec.width;
    out.height = spec.height;
    out.rgba.assign(decoded, 255);
    for (std::size_t i = 0, n = std::size_t(spec.width) * std::size_t(spec.height); i < n; ++i) {
        const std::uint8_t* p = pixels.data() + i * std::size_t(channels);
        std::uint8_t* q = out.rgba.data() + i * 4;
        // Grey is RGB alike; grey + alpha keeps its alpha.
        const bool grey = channels <= 2;
        q[0] = p[0];
        q[1] = grey ? p[0] : p[1];
        q[2] = grey ? p[0] : p[2];
        if (channels == 2) q[3] = p[1];
        if (channels == 4) q[3] = p[3];
    }
    return true;
}

}  // namespace strata

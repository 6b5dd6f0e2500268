#include "scene/image_decode.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>

namespace strata {
namespace {

struct Size {
    std::uint64_t width = 0, height = 0;
};

// A format Strata reads: its OpenImageIO reader and how its header gives the size.
struct Format {
    const char* reader;  // OpenImageIO format name
    bool (*size)(const unsigned char*, std::size_t, Size&);
};

bool isKtx2(const unsigned char* b, std::size_t n) {
    static const unsigned char magic[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
    return n >= 12 && std::memcmp(b, magic, 12) == 0;
}

std::uint32_t be16(const unsigned char* p) { return std::uint32_t(p[0]) << 8 | p[1]; }
std::uint32_t be32(const unsigned char* p) { return be16(p) << 16 | be16(p + 2); }
std::uint32_t le16(const unsigned char* p) { return std::uint32_t(p[1]) << 8 | p[0]; }
std::uint32_t le24(const unsigned char* p) { return std::uint32_t(p[2]) << 16 | le16(p); }

// The size an image's header declares is read here rather than trusted to the readers: some
// allocate for the whole image when they open it (OpenImageIO's WebP reader its decoded pixels,
// libjpeg a progressive file's coefficients), before the limits could be checked on their spec.

// PNG: the IHDR chunk must come first (PNG specification 11.2.2).
bool pngSize(const unsigned char* b, std::size_t n, Size& size) {
    if (n < 24 || std::memcmp(b + 12, "IHDR", 4) != 0) return false;
    size = {be32(b + 16), be32(b + 20)};
    return true;
}

// JPEG: the first start-of-frame marker (SOF0..SOF15 but DHT, JPG and DAC) before the scan.
bool jpegSize(const unsigned char* b, std::size_t n, Size& size) {
    std::size_t i = 2;
    while (i + 4 <= n) {
        if (b[i] != 0xFF) return false;
        const unsigned char marker = b[i + 1];
        if (marker == 0xFF) { ++i; continue; }  // fill byte
        if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) { i += 2; continue; }  // no length
        if (marker == 0xDA || marker == 0xD9) return false;  // scan or end before any frame
        const std::size_t length = be16(b + i + 2);
        if (length < 2) return false;
        const bool frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (frame) {
            if (i + 9 > n) return false;
            size = {be16(b + i + 7), be16(b + i + 5)};  // precision, height, width
            return true;
        }
        i += 2 + length;
    }
    return false;
}

// WebP: the first chunk of a RIFF/WEBP file is VP8 (lossy), VP8L (lossless) or VP8X (extended,
// with the canvas size).
bool webpSize(const unsigned char* b, std::size_t n, Size& size) {
    if (n < 30) return false;
    const unsigned char* d = b + 20;  // the first chunk's data
    if (std::memcmp(b + 12, "VP8 ", 4) == 0) {
        if (d[3] != 0x9D || d[4] != 0x01 || d[5] != 0x2A) return false;  // key frame start code
        size = {le16(d + 6) & 0x3FFF, le16(d + 8) & 0x3FFF};
        return true;
    }
    if (std::memcmp(b + 12, "VP8L", 4) == 0) {
        if (d[0] != 0x2F) return false;
        const std::uint32_t bits = le24(d + 1) | std::uint32_t(d[4]) << 24;
        size = {(bits & 0x3FFF) + 1, ((bits >> 14) & 0x3FFF) + 1};
        return true;
    }
    if (std::memcmp(b + 12, "VP8X", 4) == 0) {
        size = {std::uint64_t(le24(d + 4)) + 1, std::uint64_t(le24(d + 7)) + 1};
        return true;
    }
    return false;
}

// The format from the magic bytes: an image in a buffer has no file name, and a data URI's or
// a bufferView's mimeType may lie.
const Format* formatOf(const unsigned char* b, std::size_t n) {
    static const Format png{"png", &pngSize}, jpeg{"jpeg", &jpegSize}, webp{"webp", &webpSize};
    if (n >= 8 && std::memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0) return &png;
    if (n >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return &jpeg;
    if (n >= 12 && std::memcmp(b, "RIFF", 4) == 0 && std::memcmp(b + 8, "WEBP", 4) == 0) return &webp;
    return nullptr;
}

// Why an image of this size is refused, or empty.
std::string sizeProblem(std::uint64_t width, std::uint64_t height) {
    const std::string dims = std::to_string(width) + "x" + std::to_string(height);
    if (width < 1 || height < 1 || width > std::uint64_t(kMaxImageSide) || height > std::uint64_t(kMaxImageSide))
        return dims + " is outside 1.." + std::to_string(kMaxImageSide) + " a side";
    if (width * height * 4 > kMaxImageBytes)
        return dims + " decodes to more than " + std::to_string(kMaxImageBytes >> 20) + " MiB";
    return {};
}

// Converts 1 to 4 channels of 8 bits to RGBA: grey is RGB alike, a missing alpha is 255.
void toRgba(const std::vector<std::uint8_t>& pixels, int channels, TextureImage& out) {
    const std::size_t n = std::size_t(out.width) * std::size_t(out.height);
    out.rgba.assign(n * 4, 255);
    const bool grey = channels <= 2;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* p = pixels.data() + i * std::size_t(channels);
        std::uint8_t* q = out.rgba.data() + i * 4;
        q[0] = p[0];
        q[1] = grey ? p[0] : p[1];
        q[2] = grey ? p[0] : p[2];
        if (channels == 2) q[3] = p[1];
        if (channels == 4) q[3] = p[3];
    }
}

// A reader's message on one line (libpng's come as several), shortened.
std::string readerError(const std::string& why, const char* fallback) {
    std::string line;
    for (char c : why.substr(0, 160)) {
        if (c == '\n' || c == '\r') {
            if (!line.empty() && line.back() != ' ') line += "; ";
        } else {
            line += c;
        }
    }
    while (!line.empty() && (line.back() == ' ' || line.back() == ';')) line.pop_back();
    return "cannot decode (" + (line.empty() ? std::string(fallback) : line) + ")";
}

// Reads an image already sized and within the limits, through the reader of its format only
// (ImageInput::open would try every other reader on failure, some of them on a file of that
// name in the current folder).
bool read(const unsigned char* bytes, std::size_t size, const Format& format, TextureImage& out, std::string& error) {
    OIIO::Filesystem::IOMemReader memory(bytes, size);
    auto input = OIIO::ImageInput::create(format.reader);
    if (!input || !input->supports("ioproxy") || !input->set_ioproxy(&memory)) {
        (void)OIIO::geterror();  // retrieved, or OpenImageIO reports it at exit
        error = std::string("cannot decode (this OpenImageIO reads no ") + format.reader + " from memory)";
        return false;
    }
    // glTF alpha is straight (unassociated): the reader must not premultiply colour by it.
    OIIO::ImageSpec config, spec;
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (!input->open(format.reader, spec, config)) {
        error = readerError(input->geterror(), "not readable");
        return false;
    }
    // The reader's own idea of the size is held to the same limits (and is what is read).
    if (std::string problem = sizeProblem(std::uint64_t(std::max(spec.width, 0)), std::uint64_t(std::max(spec.height, 0)));
        !problem.empty()) {
        error = problem;
        return false;
    }
    const int channels = spec.nchannels;
    if (channels < 1 || channels > 4) {
        error = std::to_string(channels) + " channels (1 to 4 expected)";
        return false;
    }
    std::vector<std::uint8_t> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
    // 16-bit and float images are converted to 8 bits by the reader.
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
        error = readerError(input->geterror(), "read failed");
        return false;
    }
    out.width = spec.width;
    out.height = spec.height;
    toRgba(pixels, channels, out);
    return true;
}

}  // namespace

bool decodeImage(const unsigned char* bytes, std::size_t size, TextureImage& out, std::string& error) {
    if (isKtx2(bytes, size)) {
        error = "KTX2 (KHR_texture_basisu) is not supported: Debian has no KTX2 decoder library";
        return false;
    }
    const Format* format = formatOf(bytes, size);
    if (!format) {
        error = "not a PNG, JPEG or WebP image";
        return false;
    }
    Size header;
    if (!format->size(bytes, size, header)) {
        error = std::string("cannot decode (its ") + format->reader + " header gives no size)";
        return false;
    }
    if (std::string problem = sizeProblem(header.width, header.height); !problem.empty()) {
        error = problem;
        return false;
    }
    try {
        return read(bytes, size, *format, out, error);
    } catch (const std::bad_alloc&) {
        error = "out of memory for its pixels";
    } catch (const std::exception& e) {  // a reader's library throwing on a corrupt file
        error = readerError(e.what(), "exception");
    }
    return false;
}

}  // namespace strata

// LayeredImpostor::serialize and deserialize: the bytes of an impostor cache file
// (impostor_cache.hpp). Layout, little-endian as written by this machine (the cache is local):
//   "STRATAIMP" version(u32)
//   settings: views, resolution, slices, peels (i32), overlap, apexFactor (f32), holeFilling (u8)
//   centre (3 f32), radius (f32), hasAlbedo (u8)
//   atlas texels (RGBA8, views x peels layers), albedo texels (the same, sRGB) when present
//   rectangles (u32 count, 4 B each), adjacency (u32 count, 2 i32 each),
//   hole slices (u32 count, each: view i32, adjacent i32, u32 n, n i32)
// Frames, quads and the vertex buffer are rebuilt from these exactly as a bake builds them.
#include "lod/layered_impostor.hpp"

#include "lod/view_directions.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <type_traits>

namespace strata::lod {
namespace {

constexpr std::string_view kMagic = "STRATAIMP";
constexpr std::uint32_t kVersion = 1;

class Writer {
public:
    template <class T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof(T));
    }
    void putBytes(const std::vector<std::uint8_t>& data) { bytes.insert(bytes.end(), data.begin(), data.end()); }
    std::vector<std::uint8_t> bytes;
};

class Reader {
public:
    explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
    template <class T>
    T get(const char* what) {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T), what);
        T v;
        std::memcpy(&v, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return v;
    }
    // The next `n` bytes, in place (the texels are uploaded from the file's bytes, not copied).
    std::span<const std::uint8_t> getBytes(std::size_t n, const char* what) {
        need(n, what);
        const auto out = bytes_.subspan(at_, n);
        at_ += n;
        return out;
    }
    // A count of items of `itemBytes` each, checked against what is left before anything is allocated.
    std::uint32_t count(std::size_t itemBytes, const char* what) {
        const auto n = get<std::uint32_t>(what);
        if (std::size_t(n) * itemBytes > bytes_.size() - at_) throw std::runtime_error(std::string(what) + " count past the end");
        return n;
    }
    bool atEnd() const { return at_ == bytes_.size(); }

private:
    void need(std::size_t n, const char* what) const {
        if (bytes_.size() - at_ < n) throw std::runtime_error(std::string("ends inside ") + what);
    }
    std::span<const std::uint8_t> bytes_;
    std::size_t at_ = 0;
};

}  // namespace

std::vector<std::uint8_t> LayeredImpostor::serialize() const {
    if (!valid()) throw std::logic_error("serialize: the impostor is not valid (" + reason_ + ")");
    Writer w;
    for (char c : kMagic) w.put(c);
    w.put(kVersion);
    w.put(std::int32_t(settings_.views)), w.put(std::int32_t(settings_.resolution)), w.put(std::int32_t(settings_.slices));
    w.put(std::int32_t(settings_.peels)), w.put(settings_.overlap), w.put(settings_.apexFactor);
    w.put(std::uint8_t(settings_.holeFilling));
    w.put(centre_), w.put(radius_);
    w.put(std::uint8_t(albedo_.id() != 0));
    w.putBytes(readLayers(atlas_.id()));
    if (albedo_.id()) w.putBytes(readLayers(albedo_.id()));
    // Level 0's rectangles and hole slices; the coarser levels are rebuilt from the atlas.
    const Level& fine = levels_[0];
    w.put(std::uint32_t(fine.rects.size()));
    for (const SliceRect& r : fine.rects) w.put(r);
    w.put(std::uint32_t(adjacency_.size()));
    for (const auto& [a, b] : adjacency_) w.put(std::int32_t(a)), w.put(std::int32_t(b));
    w.put(std::uint32_t(fine.holeSlices.size()));
    for (const auto& [pair, slices] : fine.holeSlices) {
        w.put(std::int32_t(pair.first)), w.put(std::int32_t(pair.second)), w.put(std::uint32_t(slices.size()));
        for (int s : slices) w.put(std::int32_t(s));
    }
    return std::move(w.bytes);
}

LayeredImpostor LayeredImpostor::deserialize(std::span<const std::uint8_t> bytes, bool mergedLevels) {
    const auto start = std::chrono::steady_clock::now();
    Reader r(bytes);
    for (char c : kMagic)
        if (r.get<char>("the header") != c) throw std::runtime_error("not an impostor file");
    if (const auto version = r.get<std::uint32_t>("the version"); version != kVersion)
        throw std::runtime_error("impostor file version " + std::to_string(version) + ", expected " + std::to_string(kVersion));
    LayeredImpostor m;
    ImpostorSettings& s = m.settings_;
    s.views = r.get<std::int32_t>("the settings"), s.resolution = r.get<std::int32_t>("the settings");
    s.slices = r.get<std::int32_t>("the settings"), s.peels = r.get<std::int32_t>("the settings");
    s.overlap = r.get<float>("the settings"), s.apexFactor = r.get<float>("the settings");
    s.holeFilling = r.get<std::uint8_t>("the settings") != 0;
    s.mergedLevels = mergedLevels;
    if (const std::string why = s.validate(); !why.empty()) throw std::runtime_error(why);
    m.centre_ = r.get<glm::vec3>("the bounds");
    m.radius_ = r.get<float>("the bounds");
    if (!(m.radius_ > 0.0f) || !std::isfinite(m.radius_) || !std::isfinite(m.centre_.x) || !std::isfinite(m.centre_.y) ||
        !std::isfinite(m.centre_.z))
        throw std::runtime_error("the bounding sphere is not finite and positive");
    const bool albedo = r.get<std::uint8_t>("the albedo flag") != 0;
    const int layers = s.views * s.peels;
    const std::size_t imageBytes = std::size_t(s.resolution) * std::size_t(s.resolution) * 4u * std::size_t(layers);
    const std::span<const std::uint8_t> atlas = r.getBytes(imageBytes, "the atlas");
    const std::span<const std::uint8_t> albedoTexels = albedo ? r.getBytes(imageBytes, "the albedo") : atlas.first(0);
    const std::size_t ranges = std::size_t(layers) * std::size_t(s.slices);
    if (r.count(sizeof(SliceRect), "the rectangles") != ranges) throw std::runtime_error("rectangle count does not match the settings");
    std::vector<SliceRect> rects(ranges);
    for (SliceRect& rect : rects) {
        rect = r.get<SliceRect>("the rectangles");
        if (!rect.empty() && (int(rect.x1) >= s.resolution || int(rect.y1) >= s.resolution || rect.y0 > rect.y1))
            throw std::runtime_error("a rectangle lies outside the image or is inverted");
    }
    auto view = [&](std::int32_t v) {
        if (v < 0 || v >= s.views) throw std::runtime_error("a view index out of range");
        return int(v);
    };
    const std::uint32_t pairs = r.count(8, "the adjacency");
    for (std::uint32_t i = 0; i < pairs; ++i) {
        const int a = view(r.get<std::int32_t>("the adjacency"));
        m.adjacency_.emplace_back(a, view(r.get<std::int32_t>("the adjacency")));
    }
    std::map<std::pair<int, int>, std::vector<int>> holes;
    const std::uint32_t holeCount = r.count(12, "the hole slices");
    for (std::uint32_t i = 0; i < holeCount; ++i) {
        const int a = view(r.get<std::int32_t>("the hole slices"));
        const int b = view(r.get<std::int32_t>("the hole slices"));
        std::vector<int>& slices = holes[{a, b}];
        slices.resize(r.count(4, "the hole slices"));
        for (int& slice : slices) {
            slice = r.get<std::int32_t>("the hole slices");
            if (slice < 0 || slice >= s.peels * s.slices) throw std::runtime_error("a hole slice out of range");
        }
    }
    if (!r.atEnd()) throw std::runtime_error("bytes after the end");

    m.directions_ = viewDirections(s.views);
    for (const auto& d : m.directions_) m.frames_.push_back(makeImpostorFrame(m.centre_, m.radius_, d, s.apexFactor));
    auto upload = [&](GLenum format, std::span<const std::uint8_t> texels) {
        gl::Texture t = layerTexture(format, s.resolution, layers);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage3D(t.id(), 0, 0, 0, 0, s.resolution, s.resolution, layers, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);  // GL's default, which other uploads assume
        return t;
    };
    m.atlas_ = upload(GL_RGBA8, atlas);
    if (albedo) m.albedo_ = upload(GL_SRGB8_ALPHA8, albedoTexels);
    // Level 0's rectangles as stored, the coarser levels' (where asked) from the atlas.
    m.buildRectangles(atlas, std::move(rects));
    m.levels_[0].holeSlices = std::move(holes);
    m.mergeHoleSlices();
    m.buildQuads();
    m.bakeMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return m;
}

}  // namespace strata::lod

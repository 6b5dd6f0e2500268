#include "lod/impostor_cache.hpp"

#include "io/atomic_file.hpp"
#include "io/bounded_read.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <system_error>
#include <type_traits>

namespace strata::lod {
namespace {

constexpr const char* kExtension = ".strata-impostor";
// The largest file a bake writes: 256 px, 32 views, 4 peels, atlas and albedo (128 MiB of
// texels) and its rectangles; anything larger is not ours.
constexpr InputLimit kImpostorFileLimit{std::uintmax_t(160) << 20, "an impostor cache file"};

// FNV-1a, 64 bits: a content key, not a defence against a crafted collision (the cache is the
// user's own folder).
class Hash {
public:
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const std::uint8_t*>(data);
        for (std::size_t i = 0; i < n; ++i) value = (value ^ p[i]) * 0x100000001b3ull;
    }
    template <class T>
    void add(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    template <class T>
    void addVector(const std::vector<T>& v) {
        add(std::uint64_t(v.size()));
        if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
    }
    std::uint64_t value = 0xcbf29ce484222325ull;
};

}  // namespace

std::filesystem::path defaultImpostorCacheFolder() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "strata" / "impostors";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "strata" / "impostors";
    return {};
}

std::uint64_t impostorKey(const Scene& scene, const std::vector<ImpostorKeyPart>& parts, const Bounds& bounds,
                          const ImpostorSettings& settings) {
    Hash h;
    const char tag[] = "strata impostor 2";  // bump with the bake or the file layout
    h.bytes(tag, sizeof tag);
    h.add(settings.views), h.add(settings.resolution), h.add(settings.slices), h.add(settings.peels);
    h.add(settings.peels > 1 ? 0.0f : settings.overlap), h.add(settings.apexFactor), h.add(settings.holeFilling);
    h.add(bounds.min), h.add(bounds.max);
    h.add(std::uint64_t(parts.size()));
    for (const ImpostorKeyPart& part : parts) {
        const Mesh& mesh = scene.meshes[std::size_t(part.mesh)];
        h.addVector(mesh.positions), h.addVector(mesh.normals), h.addVector(mesh.indices);
        h.add(part.transform);
        const BakeMaterial& material = part.material;
        h.add(material.scene != nullptr);
        if (!material.scene) continue;
        const BaseColorDetail d = material.scene->baseColorDetail(material.objectIndex);
        h.add(d.textured), h.add(d.transform), h.add(d.texCoord), h.add(d.vertexColor), h.add(d.factorAlpha), h.add(d.alphaCutoff);
        const Material& m = material.scene->scene().materials[std::size_t(material.scene->objects()[std::size_t(material.objectIndex)].material)];
        h.add(m.baseColor), h.add(m.alpha), h.add(m.alphaMode), h.add(m.alphaCutoff);
        if (d.textured && m.baseColorTexture.present()) {
            h.add(m.baseColorTexture.sampler);
            const TextureImage& image = material.scene->scene().images[std::size_t(m.baseColorTexture.image)];
            h.add(image.width), h.add(image.height);  // the same bytes in another shape are another texture
            h.addVector(image.rgba);
            h.addVector(mesh.texCoords[std::clamp(d.texCoord, 0, 1)]);
        }
        if (d.vertexColor) h.addVector(mesh.colors);
    }
    return h.value;
}

std::uint64_t impostorKey(const Scene& scene, int meshIndex, const ImpostorSettings& settings, const BakeMaterial& material) {
    return impostorKey(scene, {{meshIndex, glm::mat4(1.0f), material}}, scene.meshes[std::size_t(meshIndex)].bounds(),
                       settings);
}

ImpostorCache::ImpostorCache(std::filesystem::path folder, std::uint64_t maxBytes)
    : folder_(std::move(folder)), maxBytes_(maxBytes) {}

std::filesystem::path ImpostorCache::pathOf(std::uint64_t key) const {
    char name[32];
    std::snprintf(name, sizeof name, "%016llx", (unsigned long long)key);
    return folder_ / (std::string(name) + kExtension);
}

bool ImpostorCache::contains(std::uint64_t key) const {
    std::error_code error;
    return std::filesystem::is_regular_file(pathOf(key), error);
}

std::optional<LayeredImpostor> ImpostorCache::load(std::uint64_t key, bool mergedLevels) {
    const std::filesystem::path path = pathOf(key);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        ++counts_.misses;
        return std::nullopt;
    }
    const auto start = std::chrono::steady_clock::now();
    try {
        const std::string bytes = readBoundedFile(path, kImpostorFileLimit);
        LayeredImpostor impostor = LayeredImpostor::deserialize(
            std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), mergedLevels);
        // Touched: eviction removes the least recently used first.
        std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), error);
        ++counts_.hits;
        counts_.loadMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return impostor;
    } catch (const std::exception&) {
        std::filesystem::remove(path, error);
        ++counts_.unreadable;
        ++counts_.misses;
        return std::nullopt;
    }
}

bool ImpostorCache::store(std::uint64_t key, const LayeredImpostor& impostor) {
    if (!impostor.valid()) return false;
    try {
        const std::vector<std::uint8_t> bytes = impostor.serialize();
        std::filesystem::create_directories(folder_);
        writeTextFile(pathOf(key), std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        ++counts_.stores;
    } catch (const std::exception&) {
        return false;
    }
    evict();
    return true;
}

void ImpostorCache::evict() {
    if (maxBytes_ == 0) return;  // no cap
    struct Entry {
        std::filesystem::path path;
        std::filesystem::file_time_type time;
        std::uint64_t bytes;
    };
    std::vector<Entry> entries;
    std::uint64_t total = 0;
    std::error_code error;
    for (const auto& e : std::filesystem::directory_iterator(folder_, error)) {
        if (!e.is_regular_file(error) || e.path().extension() != kExtension) continue;
        const std::uint64_t bytes = e.file_size(error);
        if (error) continue;  // gone meanwhile (another run evicting)
        entries.push_back({e.path(), e.last_write_time(error), bytes});
        total += bytes;
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.time < b.time; });
    for (const Entry& e : entries) {
        if (total <= maxBytes_) break;
        if (std::filesystem::remove(e.path, error)) {
            total -= e.bytes;
            ++counts_.evicted;
        }
    }
}

}  // namespace strata::lod

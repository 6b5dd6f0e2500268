#pragma once
// Baked impostors kept on disk, so a second run loads what the first baked (issue: "baking costs
// nothing twice"). A bake is keyed by the content of what it bakes, not by file names: each part's
// mesh (positions, normals, indices) and placement, and the bounds; for a bake that keeps material detail
// (BakeMaterial) what of the material it keeps (the base colour detail, the texture's texels
// and sampler, the texture coordinates, COLOR_0); and the impostor settings. Change any of them
// and the key changes; a stale file is never read for a new input.
//
// Files are <folder>/<16 hex digits>.strata-impostor, written atomically (io/atomic_file.hpp).
// Loading one touches it, and a store that takes the folder past its cap removes the least
// recently used files first. A file that does not read (another version, a damaged disk) is
// removed and counted; the impostor is then baked as if it had never been cached.
#include "lod/layered_impostor.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace strata::lod {

// $XDG_CACHE_HOME/strata/impostors, else $HOME/.cache/strata/impostors; empty when neither is set.
std::filesystem::path defaultImpostorCacheFolder();

// One part of a bake as its key sees it: the mesh, its placement in the impostor's space, and
// the material detail its albedo keeps (when the scene is set).
struct ImpostorKeyPart {
    int mesh = 0;
    glm::mat4 transform{1.0f};
    BakeMaterial material;
};

// The content key of baking `parts` of `scene` inside `bounds` with `settings`.
std::uint64_t impostorKey(const Scene& scene, const std::vector<ImpostorKeyPart>& parts, const Bounds& bounds,
                          const ImpostorSettings& settings);
// Of baking one mesh, in its own space and bounds (and `material`'s detail when its scene is set).
std::uint64_t impostorKey(const Scene& scene, int meshIndex, const ImpostorSettings& settings,
                          const BakeMaterial& material);

struct ImpostorCacheCounts {
    int hits = 0, misses = 0, stores = 0, evicted = 0, unreadable = 0;
    double loadMs = 0.0;  // spent loading hits
};

class ImpostorCache {
public:
    // `maxBytes`: the folder's cap, 0 for none (files of other programs in it are not counted or
    // touched).
    explicit ImpostorCache(std::filesystem::path folder, std::uint64_t maxBytes = kDefaultMaxBytes);

    static constexpr std::uint64_t kDefaultMaxBytes = 2ull << 30;  // 2 GiB

    const std::filesystem::path& folder() const { return folder_; }
    bool contains(std::uint64_t key) const;
    // The impostor stored under `key` on the current GL context, or nullopt (a miss, or a file
    // that did not read: removed).
    std::optional<LayeredImpostor> load(std::uint64_t key, bool mergedLevels = false);
    // Stores a valid impostor under `key`, then evicts down to the cap. A store that fails (a full
    // disk, a folder that cannot be made) is not an error of the run: it returns false.
    bool store(std::uint64_t key, const LayeredImpostor& impostor);

    const ImpostorCacheCounts& counts() const { return counts_; }
    std::filesystem::path pathOf(std::uint64_t key) const;

private:
    void evict();

    std::filesystem::path folder_;
    std::uint64_t maxBytes_;
    ImpostorCacheCounts counts_;
};

}  // namespace strata::lod

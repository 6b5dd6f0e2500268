#pragma once
// glTF 2.0 (.gltf and .glb) to strata::Scene. CPU only. Materials bring their base colour factor
// and texture (decoded to Scene::images through image_decode.hpp: PNG, JPEG, WebP; from files,
// data URIs and GLB bufferViews), sampler, TEXCOORD set and KHR_texture_transform; primitives
// bring TEXCOORD_0, TEXCOORD_1 and COLOR_0. A missing, broken, oversized or unsupported image is
// never fatal: it is a warning naming the image and its materials, which render with their factors.
// The other textures (metallic-roughness, normal, occlusion, emissive) are named as not drawn.
#include "scene/load_error.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace strata {

// What the loader dropped, ignored or repaired in a file it could still draw. The commands print
// `warnings` on stderr: a file the Khronos validator rejects, or one whose skins, images or
// textures are not drawn, never loads in silence.
struct GltfLoadReport {
    int skippedPrimitives = 0;           // POINTS and LINES* primitives (not drawable as surfaces)
    int flatNormalMeshes = 0;            // meshes without (usable) NORMAL that got flat normals
    // One line each, "<file>: <what was ignored> (<first place>, and N more)": one line per kind
    // of thing however many primitives show it (gltf_ignored.hpp); tinygltf's own warnings too.
    std::vector<std::string> warnings;
};

// Loads a glTF file. Scene::name is the file stem; materials[0] is a default material and
// glTF material i is materials[i + 1]; every triangle primitive becomes one Mesh and a node's
// `meshes` lists those of its glTF mesh. Throws LoadError("<file>: <what is wrong>").
// The file and every buffer it names are read through readBoundedFile (io/bounded_read.hpp):
// regular files of at most kGltfLimit bytes each. Every number that becomes a float (node
// transforms, alphaCutoff, KHR_texture_transform) is checked as a float, and every node's world
// transform must be finite. Images are bounded per image (image_decode.hpp) and to 1 GiB decoded
// per file. A file whose extensionsRequired names an extension Strata does not implement is refused.
Scene loadGltf(const std::filesystem::path& file);
Scene loadGltf(const std::filesystem::path& file, GltfLoadReport& report);

// The same from the file's bytes already in memory; `file` names it in messages and its folder
// is where external buffers are found.
Scene loadGltfFromMemory(const std::string& bytes, const std::filesystem::path& file, GltfLoadReport& report);

}  // namespace strata

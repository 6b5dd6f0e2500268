#pragma once
// What the glTF loader ignores, drops or repairs in a file it can still draw, said once per kind
// of thing (DESIGN.md: never silently wrong). A file the Khronos validator rejects, such as one
// with TEXCOORD_1 but no TEXCOORD_0, must not load in silence; neither may a valid file whose
// skins, morph targets or textures Strata does not draw.
// Internal to the loader (gltf_loader.cpp); the lines reach callers through GltfLoadReport.
#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace strata::detail {

// One line per kind however often it occurs: a model of 500 primitives with the same gap in its
// TEXCOORD sets gives one line naming the first place and how many more, not 500.
class IgnoredLog {
public:
    // `kind` groups occurrences; the first occurrence's `message` and `place` are kept.
    void note(const std::string& kind, const std::string& message, const std::string& place = {});
    // "<file>: <message> (<place>, and N more)", in the order kinds were first seen.
    std::vector<std::string> lines(const std::string& file) const;

private:
    struct Entry {
        std::string kind, message, place;
        int more = 0;
    };
    std::vector<Entry> entries_;
};

// The attributes of a triangle primitive Strata does not read, and the broken ones: an indexed
// set (TEXCOORD_n, COLOR_n, JOINTS_n, WEIGHTS_n) with a gap, an unknown semantic, colour and
// texture coordinate sets past COLOR_0 and TEXCOORD_1, morph targets.
void noteIgnoredAttributes(const tinygltf::Primitive& primitive, const std::string& place, IgnoredLog& log);

// Whole-document features Strata does not draw: extensions it does not implement, skins,
// animations, the textures it does not read yet (metallic-roughness, normal, occlusion, emissive).
void noteIgnoredFeatures(const tinygltf::Model& model, IgnoredLog& log);

// Extensions whose content the loader reads (KHR_materials_volume, KHR_mesh_quantization,
// KHR_texture_transform); a file may require only these.
bool implementedExtension(const std::string& name);

// The first of `extensionsRequired` Strata does not implement, or empty: the glTF specification
// requires a loader to refuse such a file.
std::string unimplementedRequiredExtension(const tinygltf::Model& model);

// The refusal's text (without the file): "requires extension X, which Strata does not implement".
std::string requiredExtensionProblem(const std::string& name);

}  // namespace strata::detail

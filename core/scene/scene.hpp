#pragma once
// The scene graph: materials, triangle meshes, nodes with local transforms, and the flattened
// list of drawable objects every renderer (GPU techniques and the CPU reference) consumes.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/texture.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace strata {

enum class AlphaMode { Opaque, Mask, Blend };

// The largest attenuation a material holds, per metre: "opaque within a micrometre". Loaders clamp
// or refuse larger values, so the shaders' exp(-tau d) and its derivatives stay finite and
// defined at d = 0 (an infinite tau, from a glTF attenuationColor of 0, would give NaN there).
constexpr float kMaxTau = 1.0e4f;

const char* to_string(AlphaMode mode);

struct Material {
    std::string name = "default";
    // glTF baseColorFactor (linear RGB and alpha). The fragment's base colour is this times the
    // base colour texture (sRGB decoded to linear) times the mesh's COLOR_0, alpha likewise.
    glm::vec3 baseColor{0.8f};
    float alpha = 1.0f;              // coverage/opacity used by the blending techniques
    TextureRef baseColorTexture;     // image -1: none
    // Metallic-roughness (glTF 3.9.2, the BRDF of its appendix B: common/shading_model.h). The
    // texture's blue channel scales metallic, its green roughness (linear values). Strata's own
    // materials are rough dielectrics; the glTF loader takes the file's (whose defaults are 1, 1).
    float metallic = 0.0f;
    float roughness = 1.0f;
    TextureRef metallicRoughnessTexture;
    // Tangent-space normal map (linear, scaled in x and y by normalScale), ambient occlusion from
    // the red channel (mixed in by occlusionStrength), and emission: emissiveFactor x
    // KHR_materials_emissive_strength in `emissive`, times the sRGB emissive texture.
    TextureRef normalTexture;
    float normalScale = 1.0f;
    TextureRef occlusionTexture;
    float occlusionStrength = 1.0f;
    glm::vec3 emissive{0.0f};
    TextureRef emissiveTexture;
    // KHR_materials_unlit: the base colour is the colour; no light, no emission.
    bool unlit = false;
    // KHR_materials_transmission (the factor; no refraction): the fraction of the dielectric base
    // that lets light through, tinted by the base colour, instead of scattering it diffusely
    // (common/shading_model.h's transmissionFilter). KHR_materials_ior sets the dielectric's
    // Fresnel reflectance. KHR_materials_volume's thicknessFactor (model units, scaled by the
    // object's transform) is the path through the medium a surface technique attenuates by tau
    // where the view ray enters it (render/gpu_scene.cpp's volume filter).
    float transmission = 0.0f;
    float ior = 1.5f;
    float thickness = 0.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;        // MASK: fragments with alpha < cutoff are discarded
    // Volumetric model (Barta & Kovacs): attenuation per metre for each colour channel and the
    // single-scattering albedo. tau = -ln(attenuationColor) / attenuationDistance for glTF
    // KHR_materials_volume; zero means "a thin surface" for the surface techniques. Both reach
    // the shaders as uTau and uAlbedo (shaders/common/surface.glsl). tau is in [0, kMaxTau].
    glm::vec3 tau{0.0f};
    glm::vec3 albedo{0.0f};
    // The material fills the object's inside (a participating medium) rather than covering a
    // thin shell: glTF KHR_materials_volume with thicknessFactor > 0, a scene JSON material with
    // "tau". The volumetric techniques render such objects by tau and albedo when their mesh is
    // closed (scene/mesh_volume.hpp); every other technique draws them as alpha surfaces.
    bool volume = false;
    bool doubleSided = true;

    // Light passes through the surface coloured (an unlit material has no transmission).
    bool transmissive() const { return transmission > 0.0f && !unlit; }
    // Shades with its transmission or ior (common/material.glsl's STRATA_TRANSMISSION build);
    // every other lit material is an opaque-base dielectric of ior 1.5, which the plain build assumes.
    bool usesTransmissionModel() const { return !unlit && (transmission > 0.0f || ior != 1.5f); }
    // Transparent materials go through the transparency technique, everything else through
    // the opaque pass (MASK is an alpha test, hence opaque). Transmissive glass is transparent
    // whatever its alpha mode.
    bool isTransparent() const { return alphaMode == AlphaMode::Blend || transmissive(); }
    // The fragment's alpha is tested against alphaCutoff in every pass that draws the object.
    bool alphaTested() const { return alphaMode == AlphaMode::Mask; }
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    bool empty() const { return min.x > max.x; }
    void extend(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void extend(const Bounds& b) { if (!b.empty()) { extend(b.min); extend(b.max); } }
    glm::vec3 center() const { return 0.5f * (min + max); }
    float radius() const { return empty() ? 0.0f : 0.5f * glm::length(max - min); }
    Bounds transformed(const glm::mat4& m) const;
};

// One triangle list with one material. Always indexed (non-indexed input gets 0..n-1).
// Normals are per vertex; a loader without normals produces flat ones by unwelding.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
    // glTF TEXCOORD_0 and TEXCOORD_1 and COLOR_0 (RGBA, linear; a VEC3 source gets alpha 1):
    // each empty or one per position.
    std::vector<glm::vec2> texCoords[2];
    std::vector<glm::vec4> colors;
    // glTF TANGENT (xyz unit, w the bitangent's sign), for normal textures: the file's, or
    // derived from the normal texture's TEXCOORD set (scene/tangents.hpp); empty or one per position.
    std::vector<glm::vec4> tangents;
    int material = 0;

    bool hasTexCoords(int set) const { return !texCoords[set].empty(); }
    bool hasColors() const { return !colors.empty(); }
    bool hasTangents() const { return !tangents.empty(); }

    std::size_t triangleCount() const { return indices.size() / 3; }
    Bounds bounds() const;
};

struct Node {
    std::string name;
    glm::mat4 local{1.0f};
    std::vector<int> children;
    std::vector<int> meshes;          // indices into Scene::meshes
    int materialOverride = -1;        // applies to this node's meshes and its descendants
    int light = -1;                   // index into Scene::lights placed by this node, -1 none
    // This node and everything below it are one unit of level of detail (lod/lod_units.hpp): a
    // scene description's object (a model instance) by default. The topmost such node on a path
    // decides; an object below none is a unit of its own.
    bool lodUnit = false;
};

// A KHR_lights_punctual light. A node places it (Node::light): at the node's origin, shining
// along the node's -Z. Colour is linear; intensity in lux (directional) or candela (point, spot).
struct Light {
    enum class Type { Directional, Point, Spot };
    std::string name;
    Type type = Type::Directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;  // point and spot: beyond it the light is windowed to 0; 0 unlimited
    float innerConeAngle = 0.0f;                    // spot, radians
    float outerConeAngle = 0.7853981633974483f;     // spot, radians (pi / 4)
};

// A camera the scene suggests (builtin scenes place one; loaded models are framed instead).
struct CameraPose {
    glm::vec3 position{0.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};   // camera looks down its local -Z
    float fovYDegrees = 50.0f;
};

// 1024 ulps (1.2e-4 relative: NVIDIA separates coplanar faces of different meshes by 256 to
// 1024 ulps at 48x36, where llvmpipe gives equal depths: docs/gpu-h100-session4.md);
// STRATA_DEBUG_DEPTH_TIE_ULPS=U makes it U for a diagnostic run of a whole test suite.
double defaultDepthTieUlps();

struct Scene {
    std::string name;
    std::vector<Material> materials;  // index 0 always exists (the default material)
    std::vector<Mesh> meshes;
    std::vector<TextureImage> images;  // decoded texture images (materials' TextureRef::image)
    std::vector<Light> lights;         // placed by nodes; none: the default rig (scene/lights.hpp)
    std::vector<Node> nodes;
    std::vector<int> roots;
    std::optional<CameraPose> camera;
    // Towards the default rig's light, world: the light of a scene without lights, and the key
    // light of the models that take one direction (volumetric scattering, screen-door points).
    glm::vec3 lightDirection = glm::normalize(glm::vec3(0.35f, 0.8f, 0.5f));
    glm::vec3 background{0.08f, 0.08f, 0.1f};                               // linear RGB
    // Transparent surfaces whose eye depths differ by at most this many float ulps (relative)
    // are one layer, composited in object order: the tie rule of render/depth_order.hpp.
    double depthTieUlps = defaultDepthTieUlps();

    int addMaterial(Material m) { materials.push_back(std::move(m)); return int(materials.size()) - 1; }
    int addMesh(Mesh m) { meshes.push_back(std::move(m)); return int(meshes.size()) - 1; }
    int addNode(Node n, int parent = -1);
};

// A drawable: one mesh placed in the world with its resolved material. `id` is the stable
// object id (depth-first order of the graph) used to break depth ties between coplanar
// surfaces; triangle index within the mesh is the primitive id.
struct Object {
    int id = 0;
    int mesh = 0;
    int material = 0;
    glm::mat4 world{1.0f};
    Bounds worldBounds;
    // The LOD unit instance the object belongs to (dense, in flatten order; a node reached by two
    // paths is two instances) and its transform below the unit's root node: world = the root's
    // world x unitLocal. An object below no Node::lodUnit is a unit of its own (identity).
    int unit = 0;
    glm::mat4 unitLocal{1.0f};
};

// Flattens the graph depth first. Throws std::runtime_error on a cycle or a bad index.
std::vector<Object> flatten(const Scene& scene);

Bounds worldBounds(const Scene& scene, const std::vector<Object>& objects);

// Counts transparent objects; a scene with none needs no transparency pass.
bool hasTransparency(const Scene& scene, const std::vector<Object>& objects);

// What a transmissive material's medium lets through where the view ray enters the object, per
// channel: exp(-tau x thickness x s), with s the object transform's mean scale (the cube root of
// its determinant's magnitude), KHR_materials_volume's "thickness in the node's coordinate
// space". 1 for a thin-walled (thickness 0) or non-transmissive material. The surface techniques
// take it once per entry, without refraction; the volumetric ones integrate tau themselves.
glm::vec3 volumeFilterOnEntry(const Material& material, const glm::mat4& world);

// Computes flat normals by unwelding (every triangle gets its own three vertices, with their
// texture coordinates and colours; tangents are dropped, as glTF requires).
void makeFlatNormals(Mesh& mesh);

}  // namespace strata

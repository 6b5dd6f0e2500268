#include "scene/gltf_loader.hpp"

#include "io/bounded_read.hpp"
#include "io/printable.hpp"
#include "scene/gltf_accessors.hpp"
#include "scene/gltf_ignored.hpp"
#include "scene/gltf_internal.hpp"
#include "scene/gltf_schema.hpp"
#include "scene/gltf_textures.hpp"
#include "scene/tangents.hpp"
#include "common/shading_model.h"

// The Debian package ships libtinygltf.so with the implementation (and its own JSON parser),
// so this file only includes the declarations; defining TINYGLTF_IMPLEMENTATION here would
// duplicate the library's symbols.
#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <limits>
#include <map>
#include <new>
#include <numeric>

namespace strata {
namespace {

using namespace detail;  // the loader's parts: gltf_internal.hpp, gltf_accessors.hpp, gltf_textures.hpp

// tinygltf reports several problems as a multi-line string; the contract is one line.
std::string oneLine(const std::string& text) {
    std::string out;
    bool pendingBreak = false;
    for (char c : text) {
        if (c == '\n' || c == '\r') { pendingBreak = !out.empty(); continue; }
        if (pendingBreak) { out += "; "; pendingBreak = false; }
        out += c;
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    return out;
}

// tinygltf reads external buffers (and images) through these: every file a glTF names is
// held to the same checks and limit as the glTF itself (a buffer URI of "." is a folder, not
// "out of memory"; /dev/zero is a device, not 4 GB of zeros).
bool fileExists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}

std::string expandPath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    try {
        std::string bytes = readBoundedFile(path, kGltfLimit);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const ReadError& e) {
        // tinygltf writes "File read error : <path> : " before this; keep only the cause.
        std::string what = e.what(), named = printable(path, 120) + ": ";
        if (err) *err = what.rfind(named, 0) == 0 ? what.substr(named.size()) : what;
        return false;
    }
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "the loader writes no files";
    return false;
}

bool finiteMatrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Real scenes nest a few dozen levels; the scene graph's consumers (flatten) recurse per level,
// so a hostile chain of a million nodes must stop here rather than overflow their stack.
constexpr int kMaxNodeDepth = 1000;

// glTF's primitive topologies to a triangle list (spec section 3.7.2.1 vertex orders).
std::vector<std::uint32_t> toTriangleList(int mode, const std::vector<std::uint32_t>& idx, bool indexed,
                                          const std::string& what) {
    std::vector<std::uint32_t> tris;
    std::size_t n = idx.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0)
            fail(what + ": TRIANGLES with " + str(n) + (indexed ? " indices" : " vertices") + " (not a multiple of 3)");
        return idx;
    }
    if (n < 3) return tris;
    tris.reserve((n - 2) * 3);
    for (std::size_t i = 0; i + 2 < n; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // Odd triangles swap their first two vertices to keep the winding consistent.
            std::size_t odd = i % 2;
            tris.insert(tris.end(), {idx[i], idx[i + 1 + odd], idx[i + 2 - odd]});
        } else {  // TRIANGLE_FAN
            tris.insert(tris.end(), {idx[i + 1], idx[i + 2], idx[0]});
        }
    }
    return tris;
}

// Normalizes normals; returns false if one is degenerate (then the mesh gets flat normals).
bool normalizeNormals(std::vector<glm::vec3>& normals) {
    for (auto& n : normals) {
        float len = glm::length(n);
        if (!(len > 1e-20f) || !std::isfinite(len)) return false;
        n /= len;
    }
    return true;
}

struct Converter {
    const tinygltf::Model& model;
    GltfLoadReport& report;
    detail::IgnoredLog& ignored;  // what the file holds that is not drawn as given, said once per kind
    GltfTextures textures;
    Scene scene;
    std::vector<std::vector<int>> meshMap;  // glTF mesh -> strata meshes (one per triangle primitive)

    void convertMaterials() {
        scene.materials.push_back(Material{});  // index 0: the default for primitives without one
        for (std::size_t i = 0; i < model.materials.size(); ++i) {
            const tinygltf::Material& g = model.materials[i];
            std::string what = "material " + str(i);
            Material m;
            m.name = g.name.empty() ? what : g.name;
            glm::vec4 factor(1.0f);
            const auto& f = g.pbrMetallicRoughness.baseColorFactor;
            if (!f.empty()) {
                if (f.size() != 4) fail(what + ": baseColorFactor must have 4 components");
                bool clamped = false;
                for (int c = 0; c < 4; ++c) {
                    if (!std::isfinite(f[std::size_t(c)])) fail(what + ": non-finite baseColorFactor");
                    factor[c] = std::clamp(float(f[std::size_t(c)]), 0.0f, 1.0f);
                    clamped = clamped || f[std::size_t(c)] < 0.0 || f[std::size_t(c)] > 1.0;
                }
                if (clamped) ignored.note("baseColorFactor range", "baseColorFactor outside [0, 1] clamped", what);
            }
            m.baseColor = glm::vec3(factor);
            m.alpha = factor.a;
            const std::string named = what + (g.name.empty() ? "" : " ('" + printable(g.name, 60) + "')");
            const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
            m.baseColorTexture = textures.textureOf(pbr.baseColorTexture, "baseColorTexture", named);
            convertSurface(g, what, named, m);
            if (g.alphaMode == "OPAQUE" || g.alphaMode.empty()) m.alphaMode = AlphaMode::Opaque;
            else if (g.alphaMode == "MASK") m.alphaMode = AlphaMode::Mask;
            else if (g.alphaMode == "BLEND") m.alphaMode = AlphaMode::Blend;
            else fail(what + ": unknown alphaMode '" + printable(g.alphaMode, 40) + "'");
            if (!std::isfinite(g.alphaCutoff) || g.alphaCutoff < 0.0)
                fail(what + ": alphaCutoff must be a finite number >= 0");
            m.alphaCutoff = toFloat(g.alphaCutoff, what + ": alphaCutoff");
            m.doubleSided = g.doubleSided;
            // Albedo stays 0 (a purely absorbing or thin surface) unless the material declares a
            // volume; then the single-scattering albedo is taken from the base colour, the only
            // colour glTF gives for what the medium scatters back.
            auto vol = g.extensions.find("KHR_materials_volume");
            if (vol != g.extensions.end()) {
                std::string vw = what + " KHR_materials_volume";
                const tinygltf::Value& ext = vol->second;
                double distance = number(ext, "attenuationDistance", std::numeric_limits<double>::infinity(), vw);
                if (std::isnan(distance) || distance <= 0.0) fail(vw + ": attenuationDistance must be > 0");
                glm::dvec3 color(1.0);
                if (ext.IsObject() && ext.Has("attenuationColor")) {
                    const tinygltf::Value& c = ext.Get("attenuationColor");
                    if (!c.IsArray() || c.ArrayLen() != 3) fail(vw + ": attenuationColor must be an array of 3 numbers");
                    for (int k = 0; k < 3; ++k) {
                        const tinygltf::Value& ck = c.Get(k);
                        if (!ck.IsNumber() || !std::isfinite(ck.GetNumberAsDouble()))
                            fail(vw + ": attenuationColor must be an array of 3 numbers");
                        color[k] = ck.GetNumberAsDouble();
                    }
                }
                bool clamped = false;
                for (int k = 0; k < 3; ++k) {
                    double tau = 0.0;  // infinite distance: no attenuation (spec default)
                    if (std::isfinite(distance)) {
                        // Colour 0 means "nothing gets through" (tau clamped to kMaxTau, scene.hpp, so
                        // volumeTransmittance in shaders/common/surface.glsl stays finite); colours
                        // above 1 cannot amplify.
                        double c = std::clamp(color[k], 0.0, 1.0);
                        clamped = clamped || c != color[k];
                        tau = c > 0.0 ? -std::log(c) / distance : double(kMaxTau);
                    }
                    m.tau[k] = float(std::clamp(tau, 0.0, double(kMaxTau)));
                }
                if (clamped)
                    ignored.note("attenuationColor range", "KHR_materials_volume attenuationColor outside [0, 1] clamped", what);
                m.albedo = m.baseColor;
                // The extension's thicknessFactor 0 (its default) declares a thin-walled material:
                // a volume only where the author gave the medium a thickness.
                const double thickness = number(ext, "thicknessFactor", 0.0, vw);
                if (!(thickness >= 0.0) || !std::isfinite(thickness)) fail(vw + ": thicknessFactor must be a finite number >= 0");
                m.volume = thickness > 0.0;
                m.thickness = float(std::min(thickness, 1.0e6));
                if (ext.IsObject() && ext.Has("thicknessTexture"))
                    ignored.note("thicknessTexture", "KHR_materials_volume thicknessTexture ignored: thicknessFactor is used", what);
            }
            scene.materials.push_back(std::move(m));
        }
        textures.warnFailedImages(report.warnings);
    }

    // Metallic-roughness, normal, occlusion and emission (glTF 3.9), KHR_materials_emissive_strength
    // and KHR_materials_unlit.
    void convertSurface(const tinygltf::Material& g, const std::string& what, const std::string& named, Material& m) {
        const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
        m.metallic = unitFactor(pbr.metallicFactor, "metallicFactor", what);
        m.roughness = unitFactor(pbr.roughnessFactor, "roughnessFactor", what);
        m.metallicRoughnessTexture = textures.textureOf(pbr.metallicRoughnessTexture, "metallicRoughnessTexture", named);
        m.normalTexture = textures.textureOf(g.normalTexture, "normalTexture", named);
        m.normalScale = toFloat(g.normalTexture.scale, what + ": normalTexture scale");
        m.occlusionTexture = textures.textureOf(g.occlusionTexture, "occlusionTexture", named);
        m.occlusionStrength = unitFactor(g.occlusionTexture.strength, "occlusionTexture strength", what);
        m.emissiveTexture = textures.textureOf(g.emissiveTexture, "emissiveTexture", named);
        if (!g.emissiveFactor.empty()) {
            if (g.emissiveFactor.size() != 3) fail(what + ": emissiveFactor must have 3 components");
            for (int c = 0; c < 3; ++c) m.emissive[c] = unitFactor(g.emissiveFactor[std::size_t(c)], "emissiveFactor", what);
        }
        auto strength = g.extensions.find("KHR_materials_emissive_strength");
        if (strength != g.extensions.end()) {
            const std::string sw = what + " KHR_materials_emissive_strength";
            const double k = number(strength->second, "emissiveStrength", 1.0, sw);
            // Bounded so that emission stays finite in a half-float target (65504).
            if (!(k >= 0.0) || !(k <= 1.0e4)) fail(sw + ": emissiveStrength must be a number in [0, 10000]");
            m.emissive *= float(k);
        }
        m.unlit = g.extensions.count("KHR_materials_unlit") > 0;
        convertTransmission(g, what, m);
    }

    // KHR_materials_transmission's factor and KHR_materials_ior (no refraction is drawn: the
    // docs/command-line.md's glTF materials section says what is modelled).
    void convertTransmission(const tinygltf::Material& g, const std::string& what, Material& m) {
        auto transmission = g.extensions.find("KHR_materials_transmission");
        if (transmission != g.extensions.end()) {
            const std::string tw = what + " KHR_materials_transmission";
            m.transmission = unitFactor(number(transmission->second, "transmissionFactor", 0.0, tw), "transmissionFactor", what);
            if (transmission->second.IsObject() && transmission->second.Has("transmissionTexture"))
                ignored.note("transmissionTexture", "KHR_materials_transmission transmissionTexture ignored: transmissionFactor is used", what);
        }
        auto ior = g.extensions.find("KHR_materials_ior");
        if (ior != g.extensions.end()) {
            const std::string iw = what + " KHR_materials_ior";
            const double value = number(ior->second, "ior", 1.5, iw);
            // The extension allows 0 as "infinite" (a perfect mirror F0 of 1) and >= 1 otherwise.
            if (!std::isfinite(value) || (value != 0.0 && value < 1.0) || value > 10.0)
                fail(iw + ": ior must be 0 or a number in [1, 10]");
            m.ior = value == 0.0 ? 1.0e4f : float(value);
        }
    }

    // A factor the specification bounds to [0, 1]: refused if not a number, clamped (and said
    // once) if outside.
    float unitFactor(double value, const char* name, const std::string& what) {
        if (!std::isfinite(value)) fail(what + ": non-finite " + name);
        if (value < 0.0 || value > 1.0) ignored.note(std::string(name) + " range", std::string(name) + " outside [0, 1] clamped", what);
        return float(std::clamp(value, 0.0, 1.0));
    }

    void convertMeshes() {
        meshMap.resize(model.meshes.size());
        for (std::size_t mi = 0; mi < model.meshes.size(); ++mi) {
            const tinygltf::Mesh& gm = model.meshes[mi];
            for (std::size_t pi = 0; pi < gm.primitives.size(); ++pi) {
                std::string what = "mesh " + str(mi) + " primitive " + str(pi);
                int mesh = convertPrimitive(gm, pi, what);
                if (mesh >= 0) meshMap[mi].push_back(mesh);
            }
        }
    }

    int convertPrimitive(const tinygltf::Mesh& gm, std::size_t pi, const std::string& what) {
        const tinygltf::Primitive& p = gm.primitives[pi];
        detail::noteIgnoredAttributes(p, what, ignored);
        int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
        if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
            mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
            ++report.skippedPrimitives;  // not surfaces: nothing for a transparency technique to do
            ignored.note("points and lines", "point and line primitives skipped: only triangles are drawn", what);
            return -1;
        }
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
            fail(what + ": unknown primitive mode " + str(mode));
        if (p.extensions.count("KHR_draco_mesh_compression"))
            fail(what + ": KHR_draco_mesh_compression is not supported");
        auto pos = p.attributes.find("POSITION");
        if (pos == p.attributes.end()) fail(what + ": no POSITION attribute");

        Mesh mesh;
        mesh.name = gm.name.empty() ? "mesh " + std::to_string(&gm - model.meshes.data()) : gm.name;
        if (gm.primitives.size() > 1) mesh.name += "#" + str(pi);
        mesh.positions = readVec3(model, pos->second, what, "POSITION");
        std::size_t vertexCount = mesh.positions.size();
        if (vertexCount > std::numeric_limits<std::uint32_t>::max())
            fail(what + ": too many vertices (" + str(vertexCount) + ")");

        std::vector<std::uint32_t> idx;
        if (p.indices >= 0) {
            idx = readIndices(model, p.indices, what);
            for (std::uint32_t i : idx)
                if (i >= vertexCount)
                    fail(what + ": index " + std::to_string(i) + " out of range (" + str(vertexCount) + " vertices)");
        } else {
            idx.resize(vertexCount);
            std::iota(idx.begin(), idx.end(), 0u);
        }
        mesh.indices = toTriangleList(mode, idx, p.indices >= 0, what);
        if (mesh.indices.empty()) {
            ignored.note("no triangles", "primitive with fewer than 3 vertices skipped: no triangles", what);
            return -1;
        }

        if (p.material >= 0) {
            if (std::size_t(p.material) >= model.materials.size())
                fail(what + ": material " + str(p.material) + " does not exist");
            mesh.material = p.material + 1;  // materials[0] is the inserted default
        }

        readMaterialAttributes(p, mesh, what);

        auto nrm = p.attributes.find("NORMAL");
        bool flat = true;
        if (nrm != p.attributes.end()) {
            mesh.normals = readVec3(model, nrm->second, what, "NORMAL");
            if (mesh.normals.size() != vertexCount)
                fail(what + ": NORMAL has " + str(mesh.normals.size()) + " elements, POSITION " + str(vertexCount));
            flat = !normalizeNormals(mesh.normals);
            if (flat) ignored.note("zero-length normals", "zero-length NORMAL: flat normals used instead", what);
        }
        if (flat) {
            makeFlatNormals(mesh);
            ++report.flatNormalMeshes;
        }
        return scene.addMesh(std::move(mesh));
    }

    // TEXCOORD_0, TEXCOORD_1 (VEC2) and COLOR_0 (VEC3 or VEC4), float or normalized integers,
    // and TANGENT (VEC4), one per position, finite. Read before flat normals unweld the mesh,
    // which carries all but the tangents.
    void readMaterialAttributes(const tinygltf::Primitive& p, Mesh& mesh, const std::string& what) {
        const std::size_t vertexCount = mesh.positions.size();
        auto checkCount = [&](std::size_t n, const char* semantic) {
            if (n != vertexCount) fail(what + ": " + semantic + " has " + str(n) + " elements, POSITION " + str(vertexCount));
        };
        const char* sets[2] = {"TEXCOORD_0", "TEXCOORD_1"};
        for (int set = 0; set < 2; ++set) {
            auto a = p.attributes.find(sets[set]);
            if (a == p.attributes.end()) continue;
            AccessorView v = checkAccessor(model, a->second, 2, false, what + " " + sets[set]);
            // KHR_mesh_quantization adds (normalized or not) bytes and shorts; 32-bit integers never.
            if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(what + " " + sets[set] + " (accessor " + str(a->second) + "): component type UNSIGNED_INT is not allowed");
            checkCount(v.count, sets[set]);
            std::vector<glm::vec2> uv(v.count);
            readAccessor(v, what + " " + sets[set], [&](std::size_t e, int c, double x) { uv[e][c] = float(x); });
            for (const auto& t : uv)
                if (!std::isfinite(t.x) || !std::isfinite(t.y)) fail(what + ": non-finite " + sets[set] + " value");
            mesh.texCoords[set] = std::move(uv);
        }
        // A VEC3 or VEC4 attribute as vec4s (absent components from `fill`), one per position, finite.
        auto accessorOf = [&](int index, const char* semantic) -> const tinygltf::Accessor& {
            if (index < 0 || std::size_t(index) >= model.accessors.size())
                fail(what + " " + semantic + ": accessor " + str(index) + " does not exist");
            return model.accessors[std::size_t(index)];
        };
        auto readVec4 = [&](int index, int components, const char* semantic, glm::vec4 fill) {
            AccessorView v = checkAccessor(model, index, components, false, what + " " + semantic);
            checkCount(v.count, semantic);
            std::vector<glm::vec4> values(v.count, fill);
            readAccessor(v, what + " " + semantic, [&](std::size_t e, int c, double x) { values[e][c] = float(x); });
            for (const auto& q : values)
                if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w))
                    fail(what + ": non-finite " + semantic + " value");
            return values;
        };
        auto color = p.attributes.find("COLOR_0");
        if (color != p.attributes.end()) {
            const std::string cw = what + " COLOR_0 (accessor " + str(color->second) + ")";
            const tinygltf::Accessor& acc = accessorOf(color->second, "COLOR_0");
            const int components = vectorComponents(acc.type);
            if (components != 3 && components != 4)
                fail(cw + ": type " + typeName(acc.type) + ", expected VEC3 or VEC4");
            // The specification allows float and normalized unsigned bytes and shorts only: an
            // integer colour read as is would be 255 times too bright.
            const bool unorm = acc.normalized && (acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                  acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
            if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !unorm)
                fail(cw + ": component type " + str(acc.componentType) + (acc.normalized ? "" : " not normalized") +
                     "; colours are FLOAT or normalized UNSIGNED_BYTE or UNSIGNED_SHORT");
            mesh.colors = readVec4(color->second, components, "COLOR_0", glm::vec4(1.0f));
        }
        auto tangent = p.attributes.find("TANGENT");
        if (tangent != p.attributes.end()) {
            const tinygltf::Accessor& acc = accessorOf(tangent->second, "TANGENT");
            if (vectorComponents(acc.type) != 4)
                fail(what + " TANGENT (accessor " + str(tangent->second) + "): type " + typeName(acc.type) +
                     ", expected VEC4");
            mesh.tangents = readVec4(tangent->second, 4, "TANGENT", glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        }
    }

    glm::mat4 localTransform(const tinygltf::Node& n, const std::string& what) {
        // Each number is checked as the float it becomes, naming the property.
        auto floats = [&](const std::vector<double>& v, const char* key, float* out) {
            for (std::size_t i = 0; i < v.size(); ++i) out[i] = toFloat(v[i], what + ": " + key);
        };
        if (!n.matrix.empty()) {
            if (n.matrix.size() != 16) fail(what + ": matrix must have 16 numbers");
            float m[16];
            floats(n.matrix, "matrix", m);
            glm::mat4 out;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) out[c][r] = m[c * 4 + r];  // column major
            return out;
        }
        glm::vec3 t(0.0f), s(1.0f);
        glm::quat q(1.0f, 0.0f, 0.0f, 0.0f);
        if (!n.translation.empty()) {
            if (n.translation.size() != 3) fail(what + ": translation must have 3 numbers");
            floats(n.translation, "translation", &t.x);
        }
        if (!n.rotation.empty()) {
            if (n.rotation.size() != 4) fail(what + ": rotation must have 4 numbers");
            float r[4];
            floats(n.rotation, "rotation", r);
            // glTF stores x, y, z, w; the length in double, as components near the float limit
            // would overflow its square.
            glm::dquat d(r[3], r[0], r[1], r[2]);
            double len = std::sqrt(glm::dot(d, d));
            if (!(len > 1e-6)) fail(what + ": rotation is a zero quaternion");
            // Beyond float round-off of a written unit quaternion (validator: ROTATION_NON_UNIT).
            if (std::abs(len - 1.0) > 1e-3)
                ignored.note("rotation not unit", "rotation is not a unit quaternion: normalized", what);
            q = glm::quat(d / len);
        }
        if (!n.scale.empty()) {
            if (n.scale.size() != 3) fail(what + ": scale must have 3 numbers");
            floats(n.scale, "scale", &s.x);
        }
        glm::mat4 m = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(q) * glm::scale(glm::mat4(1.0f), s);
        if (!finiteMatrix(m)) fail(what + ": translation, rotation and scale overflow a float together");
        return m;
    }

    // Every node's world transform (its ancestors' times its own) must be finite in float: a
    // chain of large scales overflows although each node's own transform is fine. Walked with
    // an explicit stack over the checked forest.
    void checkWorldTransforms() const {
        std::vector<std::pair<int, glm::mat4>> stack;
        for (int r : scene.roots) stack.push_back({r, glm::mat4(1.0f)});
        while (!stack.empty()) {
            auto [index, parentWorld] = stack.back();
            stack.pop_back();
            const Node& node = scene.nodes[std::size_t(index)];
            glm::mat4 world = parentWorld * node.local;
            if (!finiteMatrix(world))
                fail("node " + str(index) + ": its transform times its ancestors' overflows a float");
            for (int c : node.children) stack.push_back({c, world});
        }
    }

    // The node graph must be a forest: every child index exists, no node has two parents and
    // no parent chain loops. Checked iteratively so a hostile file cannot overflow the stack.
    std::vector<int> checkForest() {
        std::size_t n = model.nodes.size();
        std::vector<int> parent(n, -1);
        for (std::size_t i = 0; i < n; ++i) {
            for (int c : model.nodes[i].children) {
                if (c < 0 || std::size_t(c) >= n) fail("node " + str(i) + ": child " + str(c) + " does not exist");
                if (std::size_t(c) == i) fail("node graph has a cycle: node " + str(i) + " is its own child");
                if (parent[std::size_t(c)] == int(i))
                    fail("node " + str(i) + " lists child " + str(c) + " twice");
                if (parent[std::size_t(c)] >= 0)
                    fail("node " + str(c) + " has two parents (nodes " + str(parent[std::size_t(c)]) + " and " +
                         str(i) + ")");
                parent[std::size_t(c)] = int(i);
            }
        }
        // 0 unknown, 1 on the current walk, 2 reaches a parentless node.
        std::vector<char> state(n, 0);
        std::vector<int> depth(n, 0);
        std::vector<std::size_t> walk;
        for (std::size_t i = 0; i < n; ++i) {
            walk.clear();
            std::size_t k = i;
            for (;;) {
                if (state[k] == 1) fail("node graph has a cycle through node " + str(k));
                if (state[k] == 2) break;
                state[k] = 1;
                walk.push_back(k);
                if (parent[k] < 0) break;
                k = std::size_t(parent[k]);
            }
            // The walk ends at a root or at a node of known depth; fill depths back down it.
            for (auto w = walk.rbegin(); w != walk.rend(); ++w) {
                state[*w] = 2;
                depth[*w] = parent[*w] < 0 ? 0 : depth[std::size_t(parent[*w])] + 1;
                if (depth[*w] > kMaxNodeDepth)
                    fail("node hierarchy deeper than " + str(kMaxNodeDepth) + " levels (node " + str(*w) + ")");
            }
        }
        return parent;
    }

    void convertNodes() {
        std::vector<int> parent = checkForest();
        for (std::size_t i = 0; i < model.nodes.size(); ++i) {
            const tinygltf::Node& g = model.nodes[i];
            std::string what = "node " + str(i);
            Node node;
            node.name = g.name.empty() ? what : g.name;
            node.local = localTransform(g, what);
            node.children = g.children;
            if (g.mesh >= 0) {
                if (std::size_t(g.mesh) >= model.meshes.size()) fail(what + ": mesh " + str(g.mesh) + " does not exist");
                node.meshes = meshMap[std::size_t(g.mesh)];
            }
            node.light = nodeLight(g, what);
            scene.nodes.push_back(std::move(node));  // 1:1 with glTF nodes, so children keep their indices
        }
        if (!model.scenes.empty() && model.defaultScene >= 0) {
            if (std::size_t(model.defaultScene) >= model.scenes.size())
                fail("default scene " + str(model.defaultScene) + " does not exist");
            std::vector<char> listed(model.nodes.size(), 0);
            for (int r : model.scenes[std::size_t(model.defaultScene)].nodes) {
                std::string what = "scene " + str(model.defaultScene);
                if (r < 0 || std::size_t(r) >= model.nodes.size()) fail(what + ": node " + str(r) + " does not exist");
                if (parent[std::size_t(r)] >= 0)
                    fail(what + ": node " + str(r) + " is not a root (its parent is node " + str(parent[std::size_t(r)]) + ")");
                if (listed[std::size_t(r)]) fail(what + ": node " + str(r) + " listed twice");
                listed[std::size_t(r)] = 1;
                scene.roots.push_back(r);
            }
        } else {
            // No default scene: show every root node (what a viewer is expected to do).
            for (std::size_t i = 0; i < model.nodes.size(); ++i)
                if (parent[i] < 0) scene.roots.push_back(int(i));
        }
    }

    // KHR_lights_punctual's lights (the document's list; nodes place them).
    void convertLights() {
        for (std::size_t i = 0; i < model.lights.size(); ++i) {
            const tinygltf::Light& g = model.lights[i];
            const std::string what = "KHR_lights_punctual light " + str(i);
            Light l;
            l.name = g.name.empty() ? "light " + str(i) : g.name;
            if (g.type == "directional") l.type = Light::Type::Directional;
            else if (g.type == "point") l.type = Light::Type::Point;
            else if (g.type == "spot") l.type = Light::Type::Spot;
            else fail(what + ": unknown type '" + printable(g.type, 40) + "'");
            if (!g.color.empty()) {
                if (g.color.size() != 3) fail(what + ": color must have 3 components");
                for (int c = 0; c < 3; ++c) l.color[c] = unitFactor(g.color[std::size_t(c)], "light color", what);
            }
            // Bounded like every input: a light brighter than the Sun's 1.2e5 lux by far would
            // overflow half-float targets at once.
            if (!(g.intensity >= 0.0) || !(g.intensity <= 1.0e6)) fail(what + ": intensity must be a number in [0, 1e6]");
            l.intensity = float(g.intensity);
            if (!(g.range >= 0.0) || !std::isfinite(g.range)) fail(what + ": range must be a finite number > 0");
            l.range = float(g.range);
            if (l.type == Light::Type::Spot) {
                const double inner = g.spot.innerConeAngle, outer = g.spot.outerConeAngle;
                if (!(inner >= 0.0) || !(outer > inner) || !(outer <= 1.5707963267948966))
                    fail(what + ": spot cone angles must satisfy 0 <= inner < outer <= pi/2");
                l.innerConeAngle = float(inner);
                l.outerConeAngle = float(outer);
            }
            scene.lights.push_back(l);
        }
    }

    // The light a node places (its KHR_lights_punctual extension), -1 for none. Past
    // gpu::kMaxLights placed lights the rest are dropped and said.
    int nodeLight(const tinygltf::Node& g, const std::string& what) {
        auto ext = g.extensions.find("KHR_lights_punctual");
        if (ext == g.extensions.end()) return -1;
        const std::string lw = what + " KHR_lights_punctual";
        const double index = number(ext->second, "light", -1.0, lw);
        if (index != std::floor(index)) fail(lw + ": light must be an integer");
        if (index < 0.0 || index >= double(scene.lights.size()))
            fail(lw + ": light " + (std::abs(index) < 1e15 ? std::to_string(std::int64_t(index)) : std::string("index")) +
                 " does not exist (the file has " + str(scene.lights.size()) + ")");
        if (placedLights >= std::size_t(gpu::kMaxLights)) {
            ignored.note("too many lights", "lights past the first " + str(std::size_t(gpu::kMaxLights)) + " ignored", what);
            return -1;
        }
        ++placedLights;
        return int(index);
    }
    std::size_t placedLights = 0;

    std::size_t reachableTriangles() const {
        std::size_t triangles = 0;
        std::vector<int> stack(scene.roots.begin(), scene.roots.end());
        while (!stack.empty()) {  // the graph is a checked forest, so this terminates
            const Node& node = scene.nodes[std::size_t(stack.back())];
            stack.pop_back();
            for (int m : node.meshes) triangles += scene.meshes[std::size_t(m)].triangleCount();
            stack.insert(stack.end(), node.children.begin(), node.children.end());
        }
        return triangles;
    }
};

tinygltf::Model parseBytes(const std::string& bytes, const std::filesystem::path& file, GltfLoadReport& report,
                           detail::IgnoredLog& ignored, GltfImageTable& images) {
    if (bytes.empty()) fail("empty file");
    // tinygltf replaces mistyped properties by defaults; refuse them instead (see gltf_schema.hpp).
    if (std::string problem = detail::checkGltfSchema(bytes, &ignored); !problem.empty()) fail(problem);
    // The container is decided by the magic bytes, not the extension (.glb renamed .gltf happens).
    bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&decodeGltfImage, &images);
    loader.SetFsCallbacks({&fileExists, &expandPath, &readWholeFile, &refuseWrite, nullptr});
    tinygltf::Model model;
    images.model = &model;  // for the callback's bufferView checks, during the load only
    std::string err, warn;
    // Buffers and images are found beside the file, as tinygltf's own file loaders do.
    const std::string baseDir = file.parent_path().string();
    // The size fits an unsigned int: kGltfLimit is far below 4 GiB.
    const auto size = static_cast<unsigned int>(bytes.size());
    bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                                   reinterpret_cast<const unsigned char*>(bytes.data()), size, baseDir)
                     : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, baseDir);
    images.model = nullptr;
    if (!ok) fail(err.empty() ? std::string("not a valid glTF file") : oneLine(err));
    if (!warn.empty()) report.warnings.push_back(printable(file.string(), 120) + ": " + printableMessage(oneLine(warn)));
    return model;
}

}  // namespace

Scene loadGltf(const std::filesystem::path& file) {
    GltfLoadReport report;
    return loadGltf(file, report);
}

Scene loadGltf(const std::filesystem::path& file, GltfLoadReport& report) {
    std::string bytes;
    try {
        bytes = readBoundedFile(file, kGltfLimit);
    } catch (const ReadError& e) {
        throw LoadError(e.what());
    }
    return loadGltfFromMemory(bytes, file, report);
}

Scene loadGltfFromMemory(const std::string& bytes, const std::filesystem::path& file, GltfLoadReport& report) {
    const std::string name = printable(file.string(), 120);
    try {
        detail::IgnoredLog ignored;
        GltfImageTable images;
        tinygltf::Model model = parseBytes(bytes, file, report, ignored, images);
        // The schema check refused these already; tinygltf's model is checked too, as it is what is drawn.
        if (std::string name = detail::unimplementedRequiredExtension(model); !name.empty())
            fail(detail::requiredExtensionProblem(name));
        Converter conv{model, report, ignored, GltfTextures(model, images, ignored, file.string()), {}, {}};
        conv.scene.name = file.stem().string();
        conv.textures.moveUsedImages(conv.scene);
        conv.convertMaterials();
        conv.convertMeshes();
        // Where a normal texture needs tangents the file did not give (or flat normals dropped).
        deriveMissingTangents(conv.scene);
        conv.convertLights();
        conv.convertNodes();
        conv.checkWorldTransforms();
        detail::noteIgnoredFeatures(model, ignored);
        if (conv.reachableTriangles() == 0) {
            std::string skipped = report.skippedPrimitives
                ? " (" + std::to_string(report.skippedPrimitives) + " point/line primitives skipped)" : "";
            fail("no triangle geometry" + skipped);
        }
        for (std::string& line : ignored.lines(file.string())) report.warnings.push_back(printableMessage(line));
        return std::move(conv.scene);
    } catch (const GltfError& e) {
        throw LoadError(name + ": " + printableMessage(e.what(), 200));
    } catch (const std::bad_alloc&) {
        // Every file is within kGltfLimit, so this is a model whose content needs more memory
        // than the machine has (a huge accessor count), not a misread file.
        throw LoadError(name + ": out of memory converting the model");
    } catch (const LoadError&) {
        throw;
    } catch (const std::exception& e) {  // tinygltf's JSON parser may throw on malformed input
        throw LoadError(name + ": " + printableMessage(oneLine(e.what()), 200));
    }
}

}  // namespace strata

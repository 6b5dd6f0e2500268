#include "reference/raycast.hpp"

#include "render/depth_order.hpp"
#include "render/shading.hpp"
#include "render/volume_composite.hpp"
#include "scene/lights.hpp"
#include "scene/mesh_volume.hpp"
#include "scene/texture_sampling.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace strata {

namespace {

// ---------------------------------------------------------------------------------------------
// Per-object BVH over world-space triangles. Median split on the longest centroid axis: simple,
// deterministic, and fast enough for the reference (the bunny's 69k triangles build in a few
// milliseconds). Node boxes are padded so float rounding of the box test can never reject a ray
// the exact triangle test would accept; a false positive only costs time.

struct BvhNode {
    glm::vec3 min{0.0f};
    std::uint32_t first = 0;  // leaf: first entry in `order`; inner: index of the left child
    glm::vec3 max{0.0f};
    std::uint32_t count = 0;  // leaf: triangle count (> 0); inner: 0 (right child = first + 1)
};

constexpr std::uint32_t kLeafSize = 4;

struct PreparedObject {
    int id = 0;
    const Mesh* mesh = nullptr;
    const Material* material = nullptr;
    std::vector<glm::vec3> positions;  // world space, float, as the GPU's vertex stage has them
    glm::dmat3 linear{1.0};            // the world's upper 3x3 (tangents transform by it)
    glm::dmat3 normalMatrix{1.0};      // inverse transpose of the world's upper 3x3
    double frontSign = 1.0;            // -1 when the world flips winding (negative determinant)
    glm::vec3 volumeFilter{1.0f};      // scene/scene.hpp's volumeFilterOnEntry, as uVolumeFilter
    std::vector<BvhNode> nodes;
    std::vector<std::uint32_t> order;  // triangle indices, leaves reference ranges of this
};

glm::vec3 padded(const glm::vec3& v, float pad) { return v + glm::vec3(pad); }

void padBox(BvhNode& n) {
    // Relative to the box's size and its distance from the origin (float spacing grows with it).
    glm::vec3 ext = n.max - n.min;
    float scale = std::max({ext.x, ext.y, ext.z, glm::length(n.max), glm::length(n.min)});
    float pad = scale * 1e-5f + 1e-30f;
    n.min = padded(n.min, -pad);
    n.max = padded(n.max, pad);
}

struct BvhBuilder {
    PreparedObject& o;
    std::vector<glm::vec3> centroids;

    glm::vec3 vertex(std::uint32_t tri, int k) const { return o.positions[o.mesh->indices[tri * 3 + k]]; }

    void build() {
        std::uint32_t n = std::uint32_t(o.mesh->triangleCount());
        o.order.resize(n);
        std::iota(o.order.begin(), o.order.end(), 0u);
        centroids.resize(n);
        for (std::uint32_t t = 0; t < n; ++t) centroids[t] = (vertex(t, 0) + vertex(t, 1) + vertex(t, 2)) / 3.0f;
        o.nodes.clear();
        o.nodes.reserve(n ? 2 * (n / kLeafSize) + 2 : 1);
        o.nodes.emplace_back();
        if (n) split(0, 0, n);
    }

    void split(std::uint32_t nodeIndex, std::uint32_t begin, std::uint32_t end) {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        glm::vec3 clo = lo, chi = hi;
        for (std::uint32_t i = begin; i < end; ++i) {
            std::uint32_t t = o.order[i];
            for (int k = 0; k < 3; ++k) { lo = glm::min(lo, vertex(t, k)); hi = glm::max(hi, vertex(t, k)); }
            clo = glm::min(clo, centroids[t]);
            chi = glm::max(chi, centroids[t]);
        }
        BvhNode node;
        node.min = lo;
        node.max = hi;
        padBox(node);
        glm::vec3 ext = chi - clo;
        int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
        if (end - begin <= kLeafSize || ext[axis] <= 0.0f) {
            node.first = begin;
            node.count = end - begin;
            o.nodes[nodeIndex] = node;
            return;
        }
        std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(o.order.begin() + begin, o.order.begin() + mid, o.order.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
        node.first = std::uint32_t(o.nodes.size());
        node.count = 0;
        o.nodes[nodeIndex] = node;
        o.nodes.emplace_back();
        o.nodes.emplace_back();
        split(node.first, begin, mid);
        split(node.first + 1, mid, end);
    }
};

// ---------------------------------------------------------------------------------------------
// Watertight ray/triangle intersection (Woop, Benthin, Wald 2013).
//
// The ray is made the +z axis of a sheared "ray space" (permute so the dominant direction axis
// is z, keeping handedness, then shear x and y). A vertex's 2D ray-space position depends only
// on the vertex and the ray, so triangles sharing an edge evaluate that edge's function from
// bit-identical inputs. The 2D coordinates are rounded to float and the edge functions computed
// in double: the products of floats are then exact, so each edge function is correctly rounded,
// its sign exact, and reversing the edge gives exactly the negated value - also under FMA
// contraction, which cannot change an exact product. This is the paper's double fallback, taken
// always (it is cheap on a CPU).
//
// Tie rule when an edge function is exactly 0: decide as if the ray were moved by an
// infinitesimal (eps, eps^2) in the 2D ray space. For edge P->Q, F(p) = (P - p) x (Q - p),
// F(eps, eps^2) = F(0) + eps (Py - Qy) + eps^2 (Qx - Px) exactly (the mixed terms cancel), so
// the edge belongs to the triangle when s (Py - Qy) > 0, or Py == Qy and s (Qx - Px) > 0, with s
// the sign of the triangle's 2D area. Because it is a genuine perturbation of one point, it is
// consistent everywhere: an edge shared by two triangles on opposite sides goes to exactly one,
// a vertex shared by a fan to exactly one, and a closed mesh is crossed an even number of times.

struct Ray {
    glm::dvec3 org{0.0};
    glm::dvec3 dir{0.0, 0.0, -1.0};
    glm::dvec3 invDir{0.0};
    int kx = 0, ky = 1, kz = 2;
    double sx = 0.0, sy = 0.0, sz = 1.0;
    double tNear = 0.0, tFar = 0.0;

    Ray(const glm::dvec3& o, const glm::dvec3& d, double n, double f) : org(o), dir(d), tNear(n), tFar(f) {
        glm::dvec3 a = glm::abs(d);
        kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (d[kz] < 0.0) std::swap(kx, ky);  // keep the winding as seen along the ray
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0 / d[kz];
        for (int k = 0; k < 3; ++k) invDir[k] = d[k] != 0.0 ? 1.0 / d[k] : 0.0;
    }
};

struct TriangleHit {
    double t = 0.0;
    double b0 = 0.0, b1 = 0.0, b2 = 0.0;  // barycentrics of vertices 0, 1, 2
    bool tie = false;                     // an edge function was exactly zero
};

// Separate statements keep a compiler from fusing across the subtraction; with float inputs the
// products are exact anyway (see above).
inline double edgeFunction(float px, float py, float qx, float qy) {
    double a = double(px) * double(qy);
    double b = double(py) * double(qx);
    return a - b;
}

inline bool ownsEdge(float px, float py, float qx, float qy, double s) {
    if (py != qy) return s * (double(py) - double(qy)) > 0.0;
    return s * (double(qx) - double(px)) > 0.0;
}

bool intersectTriangle(const Ray& r, const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2, TriangleHit& hit) {
    const glm::dvec3 a = glm::dvec3(v0) - r.org;
    const glm::dvec3 b = glm::dvec3(v1) - r.org;
    const glm::dvec3 c = glm::dvec3(v2) - r.org;
    const float ax = float(a[r.kx] - r.sx * a[r.kz]), ay = float(a[r.ky] - r.sy * a[r.kz]);
    const float bx = float(b[r.kx] - r.sx * b[r.kz]), by = float(b[r.ky] - r.sy * b[r.kz]);
    const float cx = float(c[r.kx] - r.sx * c[r.kz]), cy = float(c[r.ky] - r.sy * c[r.kz]);
    // U: edge C->B (weights A), V: edge A->C (weights B), W: edge B->A (weights C).
    const double u = edgeFunction(cx, cy, bx, by);
    const double v = edgeFunction(ax, ay, cx, cy);
    const double w = edgeFunction(bx, by, ax, ay);
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    const double det = u + v + w;
    if (det == 0.0) return false;  // edge-on in ray space: the rasterizer draws nothing either
    const double s = det > 0.0 ? 1.0 : -1.0;
    bool tie = false;
    if (u == 0.0) { if (!ownsEdge(cx, cy, bx, by, s)) return false; tie = true; }
    if (v == 0.0) { if (!ownsEdge(ax, ay, cx, cy, s)) return false; tie = true; }
    if (w == 0.0) { if (!ownsEdge(bx, by, ax, ay, s)) return false; tie = true; }
    const double az = r.sz * a[r.kz], bz = r.sz * b[r.kz], cz = r.sz * c[r.kz];
    const double t = (u * az + v * bz + w * cz) / det;
    if (!(t >= r.tNear && t <= r.tFar)) return false;  // GL clips to [near, far] inclusive
    hit.t = t;
    hit.b0 = u / det;
    hit.b1 = v / det;
    hit.b2 = w / det;
    hit.tie = tie;
    return true;
}

bool rayHitsBox(const Ray& r, const BvhNode& n, double tMax) {
    double lo = r.tNear, hi = tMax;
    for (int k = 0; k < 3; ++k) {
        if (r.dir[k] == 0.0) {
            if (r.org[k] < n.min[k] || r.org[k] > n.max[k]) return false;
            continue;
        }
        double t0 = (double(n.min[k]) - r.org[k]) * r.invDir[k];
        double t1 = (double(n.max[k]) - r.org[k]) * r.invDir[k];
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
        if (lo > hi) return false;
    }
    return true;
}

// Calls visit(triangle, hit) for every triangle of `o` hit within [tNear, limit()], where
// limit() may shrink as hits are found (nearest-hit search).
template <class Visit, class Limit>
void traverse(const PreparedObject& o, const Ray& r, Visit&& visit, Limit&& limit) {
    if (o.nodes.empty() || o.order.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    const auto& idx = o.mesh->indices;
    while (top > 0) {
        const BvhNode& n = o.nodes[stack[--top]];
        if (!rayHitsBox(r, n, limit())) continue;
        if (n.count > 0) {
            for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                std::uint32_t t = o.order[i];
                TriangleHit h;
                if (intersectTriangle(r, o.positions[idx[3 * t]], o.positions[idx[3 * t + 1]],
                                      o.positions[idx[3 * t + 2]], h) && h.t <= limit())
                    visit(t, h);
            }
        } else {
            // Median splits keep the depth near log2(n / 4); 64 is far beyond any real mesh.
            if (top + 2 > 64) throw std::logic_error("raycast: BVH deeper than the traversal stack");
            stack[top++] = n.first + 1;
            stack[top++] = n.first;
        }
    }
}

bool frontFacing(const PreparedObject& o, std::uint32_t tri, const glm::dvec3& dir) {
    const auto& idx = o.mesh->indices;
    glm::dvec3 a(o.positions[idx[3 * tri]]), b(o.positions[idx[3 * tri + 1]]), c(o.positions[idx[3 * tri + 2]]);
    // Counter-clockwise is front in object space; a mirroring world keeps that face the front.
    glm::dvec3 front = o.frontSign * glm::cross(b - a, c - a);
    return glm::dot(front, dir) < 0.0;
}

// The material's base colour and alpha at the hit: factor x texture x COLOR_0, sampled by the
// GPU's rules (scene/texture_sampling.hpp).
glm::vec4 baseColorAtHit(const Scene& scene, const PreparedObject& o, std::uint32_t tri, const TriangleHit& h) {
    return baseColorAt(scene, *o.material, *o.mesh, tri, glm::dvec3(h.b0, h.b1, h.b2));
}

// A MASK material's hit exists only where its alpha reaches the cutoff (the GPU's wrapped
// builds discard the rest in every pass).
bool maskRejects(const Scene& scene, const PreparedObject& o, std::uint32_t tri, const TriangleHit& h) {
    return o.material->alphaTested() && !alphaMaskKeeps(baseColorAtHit(scene, o, tri, h).a, o.material->alphaCutoff);
}

// The interpolated value of a per-vertex attribute at the hit.
template <class T>
glm::dvec4 interpolate(const std::vector<T>& values, const std::uint32_t* idx, const TriangleHit& h) {
    return h.b0 * glm::dvec4(values[idx[0]]) + h.b1 * glm::dvec4(values[idx[1]]) + h.b2 * glm::dvec4(values[idx[2]]);
}

// The hit point as the GPU interpolates it: the triangle's world-space (float) vertices.
glm::vec3 interpolatedPosition(const PreparedObject& o, const std::uint32_t* idx, const TriangleHit& h) {
    return glm::vec3(h.b0 * glm::dvec3(o.positions[idx[0]]) + h.b1 * glm::dvec3(o.positions[idx[1]]) +
                     h.b2 * glm::dvec3(o.positions[idx[2]]));
}

// What a hit shows: its shaded colour and, for a transmissive material, what it lets through
// (common/shade_material.glsl's shadeTransmissive); zero otherwise.
struct ShadedHit {
    glm::vec3 color{0.0f};
    glm::vec3 transmitted{0.0f};
};

// The shading at a hit seen along `direction`: the material at the point (scene/
// texture_sampling.hpp) through common/shading_model.h, as common/surface.glsl does per fragment.
ShadedHit shadeHit(const Scene& scene, const std::vector<gpu::PunctualLight>& lights, const PreparedObject& o,
                   std::uint32_t tri, const TriangleHit& h, const glm::vec3& baseColor, const glm::dvec3& direction) {
    const Material& material = *o.material;
    if (material.unlit) return {baseColor};
    const Mesh& mesh = *o.mesh;
    const std::uint32_t* idx = mesh.indices.data() + 3 * tri;
    glm::dvec3 normal;
    if (mesh.normals.size() == mesh.positions.size()) {
        normal = o.normalMatrix * glm::dvec3(h.b0 * glm::dvec3(mesh.normals[idx[0]]) +
                                             h.b1 * glm::dvec3(mesh.normals[idx[1]]) +
                                             h.b2 * glm::dvec3(mesh.normals[idx[2]]));
    } else {
        glm::dvec3 a(o.positions[idx[0]]), b(o.positions[idx[1]]), c(o.positions[idx[2]]);
        normal = glm::cross(b - a, c - a);
    }
    double len = glm::length(normal);
    glm::vec3 n = len > 0.0 ? glm::vec3(normal / len) : glm::vec3(0.0f);
    const glm::vec3 interpolated = n;
    const glm::dvec3 bary(h.b0, h.b1, h.b2);
    if (usesNormalTexture(scene, material, mesh)) {
        const glm::dvec4 t = interpolate(mesh.tangents, idx, h);
        const glm::vec4 worldTangent(glm::vec3(o.linear * glm::dvec3(t)), float(t.w));
        const glm::vec4 texel = textureAt(scene, material.normalTexture, TexelEncoding::Linear, mesh, tri, bary);
        n = gpu::normalFromMap(n, worldTangent, glm::vec3(texel), material.normalScale);
    }
    const MaterialPoint m = materialAt(scene, material, mesh, tri, bary);
    const glm::vec3 toEye = glm::vec3(-glm::normalize(direction));
    // common/lighting.glsl's shadeLit: the environment, emission and each light.
    const glm::vec3 facing = gpu::normalFacingEye(n, toEye);
    // Without STRATA_TRANSMISSION the GPU takes transmission 0 and ior 1.5: Material's defaults.
    const glm::vec3 diffuse = gpu::diffuseAlbedo(baseColor, m.metallic, material.transmission);
    const glm::vec3 f0 = gpu::specularF0(baseColor, m.metallic, material.ior);
    ShadedHit out;
    out.color = gpu::environmentAndEmission(diffuse, f0, m.roughness, m.occlusion, m.emissive, facing, toEye);
    const glm::vec3 at = interpolatedPosition(o, idx, h);
    for (const gpu::PunctualLight& light : lights)
        out.color += gpu::reflectedLight(diffuse, f0, m.roughness, facing, toEye, gpu::lightToward(light, at),
                                         gpu::lightIrradianceAt(light, at));
    if (material.transmissive()) {
        out.transmitted = gpu::transmissionFilter(baseColor, m.metallic, material.transmission, material.ior,
                                                  glm::dot(facing, toEye));
        if (glm::dot(interpolated, toEye) > 0.0f) out.transmitted *= o.volumeFilter;
    }
    return out;
}

}  // namespace

struct RaycastReference::Impl {
    const Scene* scene = nullptr;
    RaycastOptions options;
    std::vector<PreparedObject> opaque;       // opaque and MASK-passing objects
    std::vector<PreparedObject> transparent;  // BLEND objects
    std::vector<gpu::PunctualLight> lights;    // scene/lights.hpp, as GpuScene uploads them
    // options.volumes: each object's classification and medium, by object id, and the volumes
    // around the last ray origin seen (every ray of an image starts at the eye).
    struct Volume {
        ObjectVolume kind;
        VolumeMedium medium;
        const Mesh* mesh = nullptr;
        glm::mat4 world{1.0f};
    };
    std::vector<Volume> volumes;
    glm::dvec3 insideOrigin{std::numeric_limits<double>::quiet_NaN()};
    MediumSet inside;

    const MediumSet& volumesAround(const glm::dvec3& origin) {
        if (origin == insideOrigin) return inside;
        inside = MediumSet();
        for (std::size_t id = 0; id < volumes.size(); ++id) {
            const Volume& v = volumes[id];
            if (v.kind.volume && containsPoint(*v.mesh, v.world, glm::vec3(origin)))
                inside.cross(int(id), v.medium, 1);
        }
        insideOrigin = origin;
        return inside;
    }

    // The walk of render/volume_composite.hpp over a sample's ordered fragments.
    glm::vec3 compositeVolumetric(const PixelSample& s, const glm::dvec3& origin, const glm::dvec3& direction,
                                  double farDepth) {
        const double scale = glm::length(direction);  // distance per unit of eye depth
        std::vector<VolumeFragment> walk;
        walk.reserve(s.fragments.size());
        for (const SurfaceFragment& f : s.fragments) {
            VolumeFragment v;
            v.distance = double(f.depth) * scale;
            v.object = f.object;
            const Volume& vol = volumes.at(std::size_t(f.object));
            if (vol.kind.volume) {
                v.medium = &vol.medium;
                v.entry = f.frontFacing == vol.kind.entersThroughFront;
            } else {
                v.color = f.color;
                v.alpha = f.alpha;
                v.coloredFilter = f.coloredFilter;
                v.transmittance = f.transmittance;
            }
            walk.push_back(v);
        }
        const double end = (s.hasOpaque ? double(s.opaqueDepth) : farDepth) * scale;
        const float ls = inscatteredRadiance(scene->lightDirection, glm::vec3(direction));
        return compositeVolumes(walk, volumesAround(origin), end, s.opaqueColor, ls).color;
    }
};

RaycastReference::RaycastReference(const Scene& scene, const std::vector<Object>& objects, RaycastOptions options)
    : impl_(std::make_unique<Impl>()) {
    impl_->scene = &scene;
    impl_->options = options;
    impl_->lights = placeLights(scene);
    for (const Object& obj : objects) {
        if (obj.mesh < 0 || obj.mesh >= int(scene.meshes.size()) || obj.material < 0 ||
            obj.material >= int(scene.materials.size()))
            throw std::runtime_error("raycast: object " + std::to_string(obj.id) + " has a bad mesh or material index");
        const Mesh& mesh = scene.meshes[obj.mesh];
        const Material& material = scene.materials[obj.material];
        // MASK whose alpha is its factor alone, below the cutoff, discards every fragment: nothing
        // to intersect. Other MASK objects are tested per hit (maskRejects).
        if (material.alphaTested() && !usesBaseColorTexture(scene, material, mesh) && !mesh.hasColors() &&
            !alphaMaskKeeps(material.alpha, material.alphaCutoff))
            continue;
        for (std::uint32_t i : mesh.indices)
            if (i >= mesh.positions.size())
                throw std::runtime_error("raycast: mesh '" + mesh.name + "' has index " + std::to_string(i) +
                                         " past its " + std::to_string(mesh.positions.size()) + " vertices");
        PreparedObject p;
        p.id = obj.id;
        p.mesh = &mesh;
        p.material = &material;
        p.positions.reserve(mesh.positions.size());
        for (const auto& v : mesh.positions) p.positions.emplace_back(obj.world * glm::vec4(v, 1.0f));
        glm::dmat3 linear(glm::dmat4(obj.world));
        p.linear = linear;
        double det = glm::determinant(linear);
        p.frontSign = det < 0.0 ? -1.0 : 1.0;
        p.normalMatrix = det != 0.0 ? glm::transpose(glm::inverse(linear)) : glm::dmat3(1.0);
        p.volumeFilter = volumeFilterOnEntry(material, obj.world);
        BvhBuilder{p, {}}.build();
        (material.isTransparent() ? impl_->transparent : impl_->opaque).push_back(std::move(p));
    }
    if (options.volumes) {
        const std::vector<ObjectVolume> kinds = classifyVolumes(scene, objects);
        for (std::size_t i = 0; i < objects.size(); ++i) {
            const Object& obj = objects[i];
            if (obj.id < 0) throw std::runtime_error("raycast: negative object id");
            if (std::size_t(obj.id) >= impl_->volumes.size()) impl_->volumes.resize(std::size_t(obj.id) + 1);
            impl_->volumes[std::size_t(obj.id)] = {kinds[i], mediumOf(scene.materials[std::size_t(obj.material)]),
                                                   &scene.meshes[std::size_t(obj.mesh)], obj.world};
        }
    }
}

RaycastReference::~RaycastReference() = default;
RaycastReference::RaycastReference(RaycastReference&&) noexcept = default;

std::size_t RaycastReference::triangleCount() const {
    std::size_t n = 0;
    for (const auto* list : {&impl_->opaque, &impl_->transparent})
        for (const auto& o : *list) n += o.mesh->triangleCount();
    return n;
}

PixelSample RaycastReference::sampleRay(const glm::dvec3& origin, const glm::dvec3& direction, double nearDepth,
                                        double farDepth) const {
    if (!(glm::length(direction) > 0.0) || !std::isfinite(glm::length(direction)))
        throw std::invalid_argument("raycast: ray direction must be finite and non-zero");
    const Scene& scene = *impl_->scene;
    const bool cull = impl_->options.cullSingleSidedBackFaces;
    PixelSample out;
    out.opaqueColor = scene.background;
    Ray ray(origin, direction, nearDepth, farDepth);
    auto culled = [&](const PreparedObject& o, std::uint32_t tri) {
        return cull && !o.material->doubleSided && !frontFacing(o, tri, direction);
    };

    // Nearest opaque hit; equal depths go to the lower (object id, primitive id), which is what
    // a GL_GREATER depth test keeps when objects are drawn in id order.
    const PreparedObject* best = nullptr;
    std::uint32_t bestTri = 0;
    TriangleHit bestHit;
    bestHit.t = farDepth;
    for (const auto& o : impl_->opaque) {
        traverse(
            o, ray,
            [&](std::uint32_t tri, const TriangleHit& h) {
                if (culled(o, tri)) return;
                if (maskRejects(scene, o, tri, h)) return;
                if (h.tie) ++out.edgeTieHits;
                bool better = !best || h.t < bestHit.t ||
                              (h.t == bestHit.t && (o.id < best->id || (o.id == best->id && tri < bestTri)));
                if (better) { best = &o; bestTri = tri; bestHit = h; }
            },
            [&] { return bestHit.t; });
    }
    if (best) {
        out.hasOpaque = true;
        out.opaqueDepth = float(bestHit.t);
        out.opaqueObject = best->id;
        out.opaquePrimitive = int(bestTri);
        out.opaqueColor =
            shadeHit(scene, impl_->lights, *best, bestTri, bestHit, glm::vec3(baseColorAtHit(scene, *best, bestTri, bestHit)), direction)
                .color;
    }

    // Every transparent hit strictly nearer than the opaque one (the GPU tests GL_GREATER
    // against the opaque depth, so an equal depth is hidden).
    const double limit = best ? bestHit.t : farDepth;
    for (const auto& o : impl_->transparent) {
        traverse(
            o, ray,
            [&](std::uint32_t tri, const TriangleHit& h) {
                if (best && !(h.t < limit)) return;
                if (culled(o, tri)) return;
                if (h.tie) ++out.edgeTieHits;
                SurfaceFragment f;
                f.depth = float(h.t);
                f.object = o.id;
                f.primitive = int(tri);
                const glm::vec4 base = baseColorAtHit(scene, o, tri, h);
                const ShadedHit shaded = shadeHit(scene, impl_->lights, o, tri, h, glm::vec3(base), direction);
                f.color = shaded.color;
                f.alpha = base.a;
                if (o.material->transmissive()) {
                    // common/surface.glsl's surfaceOptics: OPAQUE glass covers its whole surface.
                    const float coverage = o.material->alphaMode == AlphaMode::Blend ? base.a : 1.0f;
                    const gpu::SurfaceOptics optics = gpu::surfaceOpticsOf(shaded.color, coverage, shaded.transmitted);
                    const glm::vec4 scalar = gpu::scalarOpacityForm(optics);
                    f.color = glm::vec3(scalar);
                    f.alpha = scalar.a;
                    f.coloredFilter = true;
                    f.transmittance = optics.transmittance;
                }
                f.frontFacing = frontFacing(o, tri, direction);
                out.fragments.push_back(f);
            },
            [&] { return limit; });
    }
    // The fragments come back in compositing order, ties resolved by the scene's tie rule.
    out.depthTies = orderFragments(out.fragments, tieToleranceFromUlps(scene.depthTieUlps));
    out.color = impl_->options.volumes ? impl_->compositeVolumetric(out, origin, direction, farDepth)
                                       : compositeOrdered(out.fragments, out.opaqueColor);
    return out;
}

void pixelRay(const Camera& camera, int width, int height, int x, int y, glm::dvec3& origin, glm::dvec3& direction) {
    // Invert the GPU's own projection matrix entries (float, as uploaded) rather than
    // recomputing the focal length, so a pixel centre maps to the same eye-space direction.
    const glm::mat4 p = camera.projection(float(width) / float(height));
    const double ndcX = (double(x) + 0.5) / double(width) * 2.0 - 1.0;
    const double ndcY = (double(y) + 0.5) / double(height) * 2.0 - 1.0;
    // Eye-space direction with z = -1: the ray parameter is then the eye depth GL clips on.
    const glm::dvec3 eyeDir(ndcX / double(p[0][0]), ndcY / double(p[1][1]), -1.0);
    const glm::dquat q = glm::normalize(glm::dquat(camera.orientation));
    origin = glm::dvec3(camera.position);
    direction = glm::mat3_cast(q) * eyeDir;
}

PixelSample RaycastReference::samplePixel(const Camera& camera, int width, int height, int x, int y) const {
    if (width <= 0 || height <= 0 || x < 0 || y < 0 || x >= width || y >= height)
        throw std::invalid_argument("raycast: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                    ") outside a " + std::to_string(width) + "x" + std::to_string(height) + " image");
    glm::dvec3 origin, direction;
    pixelRay(camera, width, height, x, y, origin, direction);
    return sampleRay(origin, direction, camera.nearPlane, camera.farPlane);
}

Image RaycastReference::render(const Camera& camera, int width, int height, ReferenceStats* stats) const {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("raycast: image size " + std::to_string(width) + "x" + std::to_string(height));
    Image image(width, height);
    ReferenceStats s;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            PixelSample p = samplePixel(camera, width, height, x, y);
            image.set(x, y, glm::vec4(p.color, 1.0f));
            ++s.pixels;
            s.fragments += p.fragments.size();
            s.maxFragmentsPerPixel = std::max(s.maxFragmentsPerPixel, int(p.fragments.size()));
            if (!p.fragments.empty()) ++s.pixelsWithFragments;
            s.tiedFragments += std::size_t(p.depthTies);
            if (p.depthTies > 0) ++s.pixelsWithTies;
            s.edgeTieHits += std::size_t(p.edgeTieHits);
        }
    }
    if (stats) *stats = s;
    return image;
}

Image raycastReference(const Scene& scene, const std::vector<Object>& objects, const Camera& camera, int width,
                       int height, ReferenceStats* stats) {
    return RaycastReference(scene, objects).render(camera, width, height, stats);
}

PixelSample samplePixel(const Scene& scene, const std::vector<Object>& objects, const Camera& camera, int width,
                        int height, int x, int y) {
    return RaycastReference(scene, objects).samplePixel(camera, width, height, x, y);
}

std::vector<SurfaceFragment> fragmentsAtPixel(const Scene& scene, const std::vector<Object>& objects,
                                              const Camera& camera, int width, int height, int x, int y) {
    return samplePixel(scene, objects, camera, width, height, x, y).fragments;
}

}  // namespace strata

#pragma once
// The exact CPU ray-cast reference: the oracle the GPU A-buffer (`abuffer`) is checked against.
//
// One ray per pixel centre (x + 0.5, y + 0.5), row 0 at the bottom (GL's convention), built
// from the same camera math as the GPU (ndc = pixel / size * 2 - 1, Camera::projection's
// focal length and aspect). Every triangle of every object is intersected with the watertight
// test of Woop, Benthin and Wald (JCGT 2013); a pixel centre exactly on a shared edge or vertex
// is given to exactly one triangle by a tie rule that is equivalent to nudging the ray by an
// infinitesimal (epsilon, epsilon^2) in the 2D ray space (see raycast.cpp), the CPU analogue
// of the rasterizer's top-left rule. Hits are clipped to [nearPlane, farPlane] in eye depth,
// as GL clips. The nearest opaque hit (ties broken by object id, then primitive id, as the
// GPU's first-drawn-wins GL_GREATER test does) gives the colour behind; every transparent
// hit strictly nearer than it becomes a SurfaceFragment, ordered by the scene's depth tie rule
// (render/depth_order.hpp) and composited front to back. Output alpha is 1.
#include "camera/camera.hpp"
#include "image/image.hpp"
#include "render/composite.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace strata {

struct RaycastOptions {
    // glTF says a material with doubleSided = false is not drawn from behind. The GPU frame
    // pipeline draws every face (GL_CULL_FACE off), so the reference does too by default; turn
    // this on only against a renderer that culls such objects (with glFrontFace flipped for
    // negative-determinant worlds, which is how `frontFacing` is defined here).
    bool cullSingleSidedBackFaces = false;
    // Render closed objects whose material declares a volume as participating media (the model
    // of render/volume_composite.hpp, what ll-volume and abuffer-volume draw) instead of alpha
    // shells. Other transparent objects stay alpha surfaces in the same walk.
    bool volumes = false;
};

// Everything one pixel's ray meets, for tests and statistics.
struct PixelSample {
    // Transparent hits strictly nearer than the opaque hit, in compositing order
    // (orderFragments in render/depth_order.hpp: depth, with near-equal depths in object order).
    std::vector<SurfaceFragment> fragments;
    bool hasOpaque = false;
    float opaqueDepth = std::numeric_limits<float>::infinity();  // eye depth
    int opaqueObject = -1;
    int opaquePrimitive = -1;
    glm::vec3 opaqueColor{0.0f};  // shaded nearest opaque hit, or the scene background
    glm::vec3 color{0.0f};        // the fragments composited over opaqueColor
    // Fragments in the same depth layer as the preceding one under the tie rule (coplanar ties: K
    // coincident surfaces give K - 1).
    int depthTies = 0;
    // Hits (opaque or transparent, before the opaque cut) decided by the edge tie rule because
    // an edge function was exactly zero. Shows the rule is exercised; not an error.
    int edgeTieHits = 0;
};

// Totals over an image, the CPU side of the bench's fragment and coplanarity figures.
struct ReferenceStats {
    std::size_t pixels = 0;
    std::size_t fragments = 0;             // transparent fragments kept (in front of opaque)
    int maxFragmentsPerPixel = 0;          // depth complexity the A-buffer must hold
    std::size_t pixelsWithFragments = 0;
    std::size_t tiedFragments = 0;         // sum of PixelSample::depthTies
    std::size_t pixelsWithTies = 0;
    std::size_t edgeTieHits = 0;

    // Share of pixels with fragments that hold at least one exact depth tie.
    double coplanarityProbability() const {
        return pixelsWithFragments ? double(pixelsWithTies) / double(pixelsWithFragments) : 0.0;
    }
};

// Prepares the objects once (world-space vertices, one BVH per object) and then answers any
// number of rays or images. Keeps a reference to `scene`: it must outlive this object.
class RaycastReference {
public:
    RaycastReference(const Scene& scene, const std::vector<Object>& objects, RaycastOptions options = {});
    ~RaycastReference();
    RaycastReference(RaycastReference&&) noexcept;
    RaycastReference& operator=(RaycastReference&&) = delete;
    RaycastReference(const RaycastReference&) = delete;
    RaycastReference& operator=(const RaycastReference&) = delete;

    // The ray through pixel (x, y) of a width x height image (row 0 at the bottom).
    PixelSample samplePixel(const Camera& camera, int width, int height, int x, int y) const;

    // A ray in world space. `direction` is scaled so that the ray parameter is eye depth
    // (its component along the camera's forward axis is 1); hits outside
    // [nearDepth, farDepth] are clipped.
    PixelSample sampleRay(const glm::dvec3& origin, const glm::dvec3& direction, double nearDepth,
                          double farDepth) const;

    Image render(const Camera& camera, int width, int height, ReferenceStats* stats = nullptr) const;

    std::size_t triangleCount() const;

private:
    struct Impl;  // world-space vertices and BVHs, kept out of this header
    std::unique_ptr<Impl> impl_;
};

// The world-space ray through pixel (x, y): origin at the eye, direction with unit eye depth.
void pixelRay(const Camera& camera, int width, int height, int x, int y, glm::dvec3& origin,
              glm::dvec3& direction);

// Convenience wrappers that prepare the scene for one call.
Image raycastReference(const Scene& scene, const std::vector<Object>& objects, const Camera& camera,
                       int width, int height, ReferenceStats* stats = nullptr);
PixelSample samplePixel(const Scene& scene, const std::vector<Object>& objects, const Camera& camera,
                        int width, int height, int x, int y);
std::vector<SurfaceFragment> fragmentsAtPixel(const Scene& scene, const std::vector<Object>& objects,
                                              const Camera& camera, int width, int height, int x, int y);

}  // namespace strata

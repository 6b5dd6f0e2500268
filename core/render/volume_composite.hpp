#pragma once
// The volumetric model of Barta and Kovacs ("Order independent transparency with per-pixel
// linked lists", section 2-3.5) on the CPU: the exact reference for ll-volume and
// abuffer-volume, which follow the same steps in shaders/oit/volume/volume_composite.glsl.
//
// A ray is cut into segments by the surfaces it crosses. In a segment of length d inside the
// volumes V (all homogeneous), the medium has tau = sum tau_o and scattering
// sigma = sum tau_o a_o (so the mixed albedo is a = sigma / tau, the paper's update), and
//   C = a L^s (1 - e^{-tau d}) = sigma L^s (1 - e^{-tau d}) / tau,   T = e^{-tau d},
// composited front to back, L += C T_before, T *= e^{-tau d}; the opaque colour behind is
// attenuated by the final T. Thin surfaces (objects that are not volumes) composite with
// their alpha in the same walk, coloured filters (glass) per channel.
//
// Where the paper keeps running (tau, a) and subtracts on exit, this keeps the set of volumes
// the ray is in, with an integer count per object, and sums the set per segment: the same
// values, but nothing is subtracted (no round-off residue, no clamping), the albedo needs no
// division, and entries and exits at one depth (touching objects, a zero-thickness part) may
// come in any order. (1 - e^{-x}) / tau is evaluated through expm1 and tends to d as tau -> 0.
//
// The set starts with the volumes that contain the eye. The paper finds them by walking the
// sorted list backwards from its far end; that start is wrong when an exit lies behind opaque
// geometry (a volume standing in the floor) or when no fragment of the volume reaches the
// pixel at all (the eye inside a room-sized volume looking at a wall). Strata tests the eye
// point against each closed mesh instead (scene/mesh_volume.hpp), once per frame, and every
// pixel starts from that set. Hits clipped by the near plane are not seen: a volume cut by
// the near plane whose mesh does not contain the eye loses the sliver between the eye and the
// near plane (at most near-plane distance times tau), on the GPU and here alike.
#include "render/composite.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace strata {

// How many volumes may overlap at one point of a ray; the GPU's VOLUME_MAX_NESTED
// (shaders/oit/volume/volume_bindings.h, checked equal where both are seen).
constexpr int kMaxNestedVolumes = 8;

// One object's medium; scatter = tau * albedo.
struct VolumeMedium {
    glm::vec3 tau{0.0f};
    glm::vec3 scatter{0.0f};
};

VolumeMedium mediumOf(const Material& material);

// L^s of section 2.1 for a view ray: ambient radiance L^a plus the directional light's
// in-scattering L^r 3/(16 pi) (1 + cos^2 theta). The constants match the surface shading
// (render/shading.hpp): L^a = kAmbient, and L^r the light's irradiance pi (1 - kAmbient), the
// value for which a white Lambert surface facing the light has radiance 1.
float inscatteredRadiance(const glm::vec3& lightDirection, const glm::vec3& viewDirection);

// (1 - e^{-tau d}) / tau, finite for tau = 0 (gives d) and for tau in the millions (1 / tau).
double segmentIntegral(double tau, double length);

// The set of volumes a ray is in, with a count per object (entries minus exits).
class MediumSet {
public:
    // +1 entering `object`, -1 leaving it. Returns false (and changes nothing) when a new object
    // would exceed the nesting limit.
    bool cross(int object, const VolumeMedium& medium, int step);
    VolumeMedium sum() const;  // the media with a positive count
    int size() const { return int(entries_.size()); }

private:
    struct Entry {
        int object;
        int count;
        VolumeMedium medium;
    };
    std::vector<Entry> entries_;
};

// A fragment as the volumetric walk reads it.
struct VolumeFragment {
    double distance = 0.0;          // along the ray from the eye
    int object = 0;
    const VolumeMedium* medium = nullptr;  // null: a thin surface, composited with alpha
    bool entry = false;             // volumes: the ray enters the object here
    glm::vec3 color{0.0f};          // thin surfaces: shaded colour and alpha
    float alpha = 0.0f;
    // A thin coloured filter (render/composite.hpp's SurfaceFragment): what passes behind it
    // per channel; alpha * color is still its premultiplied colour.
    bool coloredFilter = false;
    glm::vec3 transmittance{1.0f};
};

struct VolumeResult {
    glm::vec3 color{0.0f};
    glm::vec3 transmittance{1.0f};
    int nestingOverflow = 0;  // volume fragments ignored past the nesting limit
};

// Walks `fragments`, already in compositing order (render/depth_order.hpp), from the eye to
// `endDistance` (the opaque surface or the far plane), starting inside `eyeInside`.
// Segment lengths are max(0, distance - the farthest distance seen), so fragments of one tie
// layer visited out of depth order partition the ray exactly.
VolumeResult compositeVolumes(const std::vector<VolumeFragment>& fragments, const MediumSet& eyeInside,
                              double endDistance, const glm::vec3& background, float inscattered);

}  // namespace strata

#pragma once
// What the volumetric resolve (shaders/oit/volume/volume_list.glsl) reads besides the lists:
// each object's medium, the volumes around the eye, the camera and light of the frame, the
// opaque depth (the last segment ends there), and a counter of nesting overflow. Shared by
// abuffer-volume and ll-volume, which differ only in their storage.
#include "gl/objects.hpp"
#include "oit/technique.hpp"

#include <cstdint>
#include <vector>

namespace strata {

class VolumeResolve {
public:
    // Whether `scene` has a volume object: without one the walk has nothing to walk through and
    // costs about 1.6-1.9x the surface resolve for the same image, so both volumetric
    // techniques draw with their surface technique's programs there.
    static bool needed(const GpuScene& scene);
    // Once per frame before the resolve: uploads the medium table, finds the volumes around the
    // eye (a point-in-mesh test per volume whose bounds hold the eye) and clears the counter.
    void prepare(const FrameContext& frame);
    // Binds the table, counter and opaque depth, and sets the walk's uniforms on `program`.
    void bind(const FrameContext& frame, GLuint program) const;
    // The output colour alone: a fragment resolve samples the opaque depth, which the frame's
    // output framebuffer holds as its depth attachment (a feedback loop if bound there).
    GLuint colorFramebuffer(const FrameContext& frame);
    // Volume fragments ignored because more than VOLUME_MAX_NESTED volumes overlapped (reads
    // the counter back: call after the resolve).
    std::uint64_t nestingOverflow() const;
    // After the resolve: the table's memory, and the ignored fragments as dropped (overflowed).
    void addStats(TechniqueStats& stats) const;
    // The volumes around the eye last prepared (object ids), for the panel and tests.
    const std::vector<int>& eyeInside() const { return eyeInside_; }
    std::uint64_t bytes() const;

private:
    gl::Buffer objects_, stats_;
    gl::Texture media_;  // objects_ as a buffer texture (BIND_VOLUME_MEDIA)
    std::size_t objectCapacity_ = 0;
    std::vector<int> eyeInside_;
    gl::Framebuffer colorFramebuffer_;
};

}  // namespace strata

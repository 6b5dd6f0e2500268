#pragma once
// The point samples of screendoor-object-sw (Sen et al. 4.1): a compute pass per transparent
// object lays about one point per supersampled pixel on each triangle and keeps each with
// probability alpha (shaders/oit/screendoor/point_samples.comp.glsl). The buffer starts small and
// grows to the count wanted, up to a capacity bound; past the bound points are counted, not kept.
#include "gl/objects.hpp"
#include "oit/screendoor/screendoor_pass.hpp"
#include "oit/technique.hpp"

#include <cstdint>

namespace strata::screendoor {

struct PointSampling {
    std::uint64_t pointsWanted = 0;     // kept samples the lattices produced
    std::uint64_t pointsStored = 0;     // min(wanted, capacity)
    std::uint64_t trianglesBounded = 0; // triangles whose lattice was coarsened to the per-triangle bound
    int regrows = 0;
};

class PointSamples {
public:
    // Samples every transparent object; binds the point buffer to BIND_POINTS.
    PointSampling sample(const FrameContext& frame, const PassParameters& parameters, std::uint64_t maxPoints,
                         double maxTriangleSamples);
    // Draws the stored points through the tile's view-projection; one draw call.
    void draw(const FrameContext& tileFrame) const;
    std::uint64_t bytes() const;

private:
    std::uint64_t run(const FrameContext& frame, const PassParameters& parameters, double maxTriangleSamples,
                      std::uint64_t& trianglesBounded);

    gl::Program sampleProgram_, drawProgram_;
    bool drawProgramPunctual_ = false;  // drawProgram_ built with STRATA_PUNCTUAL_LIGHTS
    gl::Buffer points_, counters_, colors_;
    std::uint64_t capacity_ = 0;
    std::uint64_t stored_ = 0;
};

}  // namespace strata::screendoor

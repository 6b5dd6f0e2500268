#pragma once
// The lights a scene is shaded by, in world space, as the shading model takes them
// (common/shading_model.h's PunctualLight): its KHR_lights_punctual lights placed by the nodes
// that reference them, or, for a scene without lights, Strata's default rig (one directional
// light along Scene::lightDirection). GpuScene uploads the list; the CPU reference loops over it.
#include "common/shading_model.h"
#include "scene/scene.hpp"

#include <vector>

namespace strata {

// At most gpu::kMaxLights, in depth-first node order (the loader refuses more). A node reached
// twice (a shared subtree) places its light twice, as it places its meshes twice.
std::vector<gpu::PunctualLight> placeLights(const Scene& scene);

// The default rig's light for `scene`.
gpu::PunctualLight defaultLight(const Scene& scene);

}  // namespace strata

#pragma once
// The one shading model every renderer uses: the CPU reference through this header, the GPU
// through shaders/common/shading.glsl, both from shaders/common/shading_model.h.
#include "common/shading_model.h"

namespace strata {

using gpu::alphaMaskKeeps;
using gpu::combineBaseColor;
using gpu::kAmbient;
using gpu::kDefaultLightIrradiance;
using gpu::shadeSurface;
using gpu::transformTexCoord;

}  // namespace strata

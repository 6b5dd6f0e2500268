// The fragment's id in the tie order (see coplanar_layer.glsl): the rank of (object id,
// primitive id) as the bits of a positive normal float, so that MAX blending orders it exactly.
#include "peel_bindings.h"

layout(std430, binding = BIND_COPLANAR_ID_BASE) readonly buffer CoplanarIdBase { uint idBase[]; };

float fragmentIdKey(uint objectId) {
    return uintBitsToFloat(idBase[objectId] + uint(gl_PrimitiveID) + 0x00800000u);
}


// Store side of the volumetric techniques: which faces of the object being drawn enter its
// volume, as flags on the node's primitive id (volume_bindings.h). Included by the store
// passes of abuffer-volume and ll-volume (abuffer_store.frag.glsl, ll_store.frag.glsl with
// VOLUME defined).
#include "oit/volume/volume_bindings.h"

// The object's uVolumeEntry (common/object_record.glsl): 0 a thin surface; +1 the ray enters
// through faces with gl_FrontFacing, -1 through the others (inward-wound meshes and mirroring
// worlds).
#include "common/object_record.glsl"

uint volumeFlags() {
    if (uVolumeEntry == 0) return 0u;
    bool entry = gl_FrontFacing == (uVolumeEntry > 0);
    return VOLUME_FLAG_MEDIUM | (entry ? VOLUME_FLAG_ENTRY : 0u);
}

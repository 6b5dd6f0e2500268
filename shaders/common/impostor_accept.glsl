// The layered impostor's alpha test, shared by every scene program's fragment wrapper
// (common/scene_main.glsl) and lod/'s hole-filling id render: does slice `slice` of `slices` accept the texel whose alpha holds depth code
// `code` (0 empty, else t = (code - 0.5) / 255 over the slab), with `overlap` slice widths of
// reach on each side? lod/layered_impostor.cpp's rectangles apply the same rule on the CPU.
#ifndef STRATA_IMPOSTOR_ACCEPT_GLSL
#define STRATA_IMPOSTOR_ACCEPT_GLSL

bool impostorAccepts(float alpha, int slice, int slices, float overlap) {
    int code = int(round(alpha * 255.0));
    if (code == 0) return false;
    float t = (float(code) - 0.5) / 255.0;
    if (overlap == 0.0) return min(int(t * float(slices)), slices - 1) == slice;
    return abs(t - (float(slice) + 0.5) / float(slices)) <= (0.5 + overlap) / float(slices);
}

#endif

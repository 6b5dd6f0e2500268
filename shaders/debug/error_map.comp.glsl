#version 450 core
// The error view: per pixel, the absolute difference between an image and the reference of the
// same frame (linear RGB), shown in false colour, and per work group the partial sums the host
// turns into RMSE, PSNR and the worst pixel (core/render/error_map.hpp).
//
// False colour of e = the largest per-channel |image - reference|, t = e / uScale:
//   e == 0 exactly:  the reference's luminance, dimmed to a dark grey (where nothing differs,
//                    the scene stays recognisable);
//   e > 0:           dark blue (t -> 0) through blue, cyan, green, yellow to red (t >= 1), so
//                    even round-off shows and anything at or above uScale is plain red.
#include "common/bindings.h"
#include "debug/error_map.h"

layout(local_size_x = ERROR_GROUP_SIZE, local_size_y = ERROR_GROUP_SIZE) in;

layout(binding = BIND_ERROR_IMAGE) uniform sampler2D uImage;
layout(binding = BIND_ERROR_REFERENCE) uniform sampler2D uReference;
layout(binding = BIND_RESOLVE_OUTPUT, rgba32f) uniform writeonly image2D uFalseColor;
layout(std430, binding = BIND_ERROR_PARTIALS) writeonly buffer ErrorPartials { ErrorPartial partials[]; };

uniform float uScale;  // the error shown as full red (> 0)

const uint kGroupPixels = ERROR_GROUP_SIZE * ERROR_GROUP_SIZE;
shared float sSum[kGroupPixels];
shared float sMax[kGroupPixels];
shared uint sPixel[kGroupPixels];

vec3 ramp(float t) {
    const float stops[18] = float[18](ERROR_RAMP_STOPS);
    float x = clamp(t, 0.0, 1.0) * 5.0;
    int i = min(int(x), 4);
    vec3 a = vec3(stops[3 * i], stops[3 * i + 1], stops[3 * i + 2]);
    vec3 b = vec3(stops[3 * i + 3], stops[3 * i + 4], stops[3 * i + 5]);
    return mix(a, b, x - float(i));
}

void main() {
    ivec2 size = textureSize(uImage, 0);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    uint local = gl_LocalInvocationIndex;
    float sum = 0.0, worst = -1.0;  // -1: outside the image, never the worst
    uint pixel = 0xffffffffu;
    if (all(lessThan(p, size))) {
        vec3 reference = texelFetch(uReference, p, 0).rgb;
        vec3 d = abs(texelFetch(uImage, p, 0).rgb - reference);
        sum = dot(d, d);
        worst = max(d.r, max(d.g, d.b));
        pixel = uint(p.y) * uint(size.x) + uint(p.x);
        vec3 shown = worst == 0.0 ? vec3(ERROR_SAME_BASE + ERROR_SAME_GAIN * clamp(dot(reference, vec3(0.2126, 0.7152, 0.0722)), 0.0, 1.0))
                                  : ramp(worst / uScale);
        imageStore(uFalseColor, p, vec4(shown, 1.0));
    }
    sSum[local] = sum;
    sMax[local] = worst;
    sPixel[local] = pixel;
    barrier();
    for (uint stride = kGroupPixels / 2u; stride > 0u; stride >>= 1u) {
        if (local < stride) {
            uint other = local + stride;
            sSum[local] += sSum[other];
            // Larger error wins; among equal errors the lower pixel index, whatever the order.
            if (sMax[other] > sMax[local] || (sMax[other] == sMax[local] && sPixel[other] < sPixel[local])) {
                sMax[local] = sMax[other];
                sPixel[local] = sPixel[other];
            }
        }
        barrier();
    }
    if (local == 0u) {
        uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
        partials[group] = ErrorPartial(sSum[0], sMax[0], sPixel[0], 0u);
    }
}

// Mirrors core/render/shading.hpp: two-sided Lambert with an ambient floor.
const float kAmbient = 0.3;

vec3 shadeSurface(vec3 baseColor, vec3 normal, vec3 lightDirection) {
    float len = length(normal);
    float ndl = len > 0.0 ? abs(dot(normal / len, lightDirection)) : 1.0;
    return baseColor * (kAmbient + (1.0 - kAmbient) * ndl);
}

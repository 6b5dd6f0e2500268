#version 450 core
// Bucket peeling's depth range: MAX blending of (z, -z) leaves the nearest depth in r and minus
// the farthest in g. Drawn with the objects' bounding boxes (the default, "range from the
// bounds") or with the geometry itself.
layout(location = 0) out vec2 outRange;

void main() {
    outRange = vec2(gl_FragCoord.z, -gl_FragCoord.z);
}

#version 450 core
// Skip queries, step 2: an object's conservative screen rectangle in the reduced bound's
// pixels, as a 4-vertex triangle strip (no vertex buffer).
uniform vec4 uRect;  // x0, y0, x1, y1 in normalized device coordinates

void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(mix(uRect.xy, uRect.zw, corner), 0.0, 1.0);
}

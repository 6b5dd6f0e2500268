// Front-to-back "under" of a colour stored as two half2 pairs (r, g) and (b, alpha), the
// layout of the A-buffer's nodes and the buffers' entries.
void compositePacked(uint colorRG, uint colorBA, inout vec3 color, inout float transmittance) {
    vec2 rg = unpackHalf2x16(colorRG);
    vec2 ba = unpackHalf2x16(colorBA);
    color += transmittance * ba.y * vec3(rg, ba.x);
    transmittance *= 1.0 - ba.y;
}

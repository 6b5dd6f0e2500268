// Front-to-back "under" of a colour stored as two half2 pairs (r, g) and (b, alpha), the
// layout of the A-buffer's nodes and the buffers' entries.
void compositePacked(uint colorRG, uint colorBA, inout vec3 color, inout float transmittance) {
    vec2 rg = unpackHalf2x16(colorRG);
    vec2 ba = unpackHalf2x16(colorBA);
    color += transmittance * ba.y * vec3(rg, ba.x);
    transmittance *= 1.0 - ba.y;
}

// A colour rounded as the packed layout rounds it: kept beside packed ones (f2b-ll's layer
// anchors), it composites bit for bit as if it had been stored, whichever fragment it is.
vec4 packedPrecision(vec4 c) {
    return vec4(unpackHalf2x16(packHalf2x16(c.rg)), unpackHalf2x16(packHalf2x16(c.ba)));
}

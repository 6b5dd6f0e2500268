// Randomness without state: a well-mixed 32-bit hash (lowbias32, Wellons) of a key built from
// (seed, object id, triangle, sample), so every random choice depends on what it is for and
// never on the order work arrives in.
uint hashUint(uint x) {
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// Uniform in [0, 1) with 24 bits.
float hashUnit(uint h) {
    return float(h >> 8) * (1.0 / 16777216.0);
}

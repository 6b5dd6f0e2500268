#pragma once
// The id the coplanarity-aware peeling variants order a layer's fragments by
// (shaders/oit/peeling/coplanar_ids.glsl): idBase[object] + primitive id, where idBase[o] is the
// number of triangles of all objects with a lower id. So ids follow the tie rule's (object id,
// primitive id) order and are unique per pixel. Uploaded per frame (one uint per object).
#include "oit/technique.hpp"

namespace strata::peeling {

class CoplanarIds {
public:
    // Fills and binds the SSBO at BIND_COPLANAR_ID_BASE. Returns false when the scene has more
    // triangles than the encoding holds (2^31 - 2^24): ids would collide, which the caller
    // reports as an overflow.
    bool bind(const FrameContext& frame);

private:
    gl::Buffer buffer_;
    std::size_t capacity_ = 0;
};

// Clear value of id channels: -FLT_MAX, below every id and every negated id.
constexpr float kNoId = -3.402823466e38f;

}  // namespace strata::peeling

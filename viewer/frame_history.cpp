#include "frame_history.hpp"

#include <algorithm>
#include <cstddef>

namespace strata {

void FrameHistory::push(float value) {
    values_[std::size_t(next_)] = value;
    next_ = (next_ + 1) % kFrames;
    count_ = std::min(count_ + 1, kFrames);
}

float FrameHistory::max() const {
    float m = 0.0f;
    for (int i = 0; i < count_; ++i) m = std::max(m, values_[std::size_t(i)]);
    return m;
}

float FrameHistory::mean() const {
    if (count_ == 0) return 0.0f;
    double s = 0.0;
    for (int i = 0; i < count_; ++i) s += values_[std::size_t(i)];
    return float(s / count_);
}

}  // namespace strata

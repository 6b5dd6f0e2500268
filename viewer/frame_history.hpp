#pragma once
// The last frames' values of one measure (GPU ms in the viewer, viewing error in degrees in the
// immersive mode), kept for the panels' plots and their mean and max.
#include <array>

namespace strata {

class FrameHistory {
public:
    static constexpr int kFrames = 240;
    void push(float value);
    int count() const { return count_; }
    // Values for ImGui::PlotLines: the ring buffer and the offset of its oldest entry.
    const float* data() const { return values_.data(); }
    int offset() const { return count_ < kFrames ? 0 : next_; }
    float max() const;
    float mean() const;

private:
    std::array<float, kFrames> values_{};
    int next_ = 0;
    int count_ = 0;
};

}  // namespace strata

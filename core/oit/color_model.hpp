#pragma once
// Which colour model a frame's transparent fragments are stored in (shaders/oit/packed_color.glsl):
// a colour and an alpha, or, in a scene with a transmissive material (GpuScene::hasColoredFilters),
// a premultiplied colour and a transmittance per channel. The techniques that composite coloured
// filters exactly (abuffer, ll, fab, kbuffer, sbuffer, bun-ll) build one program set per model on
// first use, so a scene without coloured filters keeps the scalar build's storage and cost; every
// other technique draws the scalar form (common/shading_model.h's scalarOpacityForm), which keeps
// a filter's brightness and loses its tint, and `strata modes` says so.
#include "gl/shader_program.hpp"
#include "render/gpu_scene.hpp"

namespace strata {

enum class ColorModel { Scalar = 0, RgbTransmittance = 1 };
inline constexpr int kColorModels = 2;

inline ColorModel colorModelFor(const GpuScene& scene) {
    return scene.hasColoredFilters() ? ColorModel::RgbTransmittance : ColorModel::Scalar;
}

inline gl::Defines withColorModel(gl::Defines defines, ColorModel model) {
    if (model == ColorModel::RgbTransmittance) defines["STRATA_RGB_TRANSMITTANCE"] = "";
    return defines;
}

// A full-screen pass (common/fullscreen.vert.glsl + `fragment`) built for `model`.
inline gl::Program buildFullscreenProgram(const std::string& fragment, ColorModel model, gl::Defines defines = {}) {
    return gl::buildProgram({"common/fullscreen.vert.glsl", fragment}, withColorModel(std::move(defines), model));
}

// A technique's program set for each colour model, each built on its first use: `use` picks
// the frame's and returns it (empty until built), `->` reaches the one picked last.
template <class Programs>
class ProgramsPerColorModel {
public:
    Programs& use(ColorModel model) {
        current_ = &sets_[int(model)];
        return *current_;
    }
    Programs* operator->() const { return current_; }

private:
    Programs sets_[kColorModels];
    Programs* current_ = nullptr;
};

}  // namespace strata

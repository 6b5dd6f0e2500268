#pragma once
// The transparency-technique interface. A technique composites the scene's transparent objects
// over the opaque image: it reads the opaque colour and depth from the frame targets and writes
// the output colour. It declares what it is (TechniqueInfo), exposes its settings, and reports
// what the last frame cost and captured (TechniqueStats).
#include "camera/camera.hpp"
#include "gl/gpu_timer.hpp"
#include "render/frame_targets.hpp"
#include "render/gpu_scene.hpp"
#include "render/screen_rect.hpp"
#include "oit/settings.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace strata {

struct TechniqueInfo {
    std::string id;
    std::string family;         // baseline, peeling, buffer, coplanarity, volumetric, approximate, reference
    // Captures every fragment at its default settings, whatever the depth complexity (memory
    // grown to the fragments present). Bounded techniques (a per-pixel or per-pool capacity:
    // kbuffer, fab, ll) are not robust even though they are exact when the capacity suffices.
    bool robust = false;
    bool handlesCoplanarity = false;
    std::string passes;         // e.g. "1", "N", "ceil(N/2)+1", "2 (+regrow)"
    std::string memoryModel;    // e.g. "none", "w*h*K*8", "pool sized to fragments"
    std::string description;
    // Composites a transmissive material's coloured filter per channel, exactly (oit/color_model.hpp);
    // the others composite its scalar form, which keeps its brightness and loses its tint.
    bool rgbTransmittance = false;
    // Its image depends on the order the objects are submitted in (plain blending, and the ties
    // of the back-to-front sort of sorted blending and crow): it draws them in object order. The
    // others draw them batched (GpuScene::transparentObjectsBatched). Their images change only
    // where the order was never defined on a GPU anyway: which fragments a full fixed array
    // (fab) keeps, which surface an exact depth tie leaves to a peeler that does not handle
    // coplanarity, and the rounding of wboit's sums.
    bool keepsSubmissionOrder = false;
};

struct TechniqueStats {
    int passes = 0;                       // geometry and full-screen passes issued
    std::uint64_t bytes = 0;              // GPU memory the technique holds
    std::uint64_t fragmentsCaptured = 0;  // fragments that reached the final composite
    std::uint64_t fragmentsDropped = 0;   // counted but not stored
    bool overflowed = false;              // something did not fit (and was dropped or approximated)
    int regrows = 0;                      // exact paths: times memory grew and the frame re-rendered
    int tiles = 1;                        // exact paths: screen tiles used
    std::uint64_t objectDraws = 0;        // draw calls issued for transparent objects
    std::uint64_t objectDrawsSkipped = 0; // draws avoided (objects already peeled, culled by queries)
    std::uint64_t fragmentsTail = 0;      // overflowed fragments blended approximately ("tail" option)
    std::uint64_t primitivesBounded = 0;  // primitives sampled coarser than asked (screendoor-object-sw's
                                          // max_triangle_samples); each also sets `overflowed`
};

struct FrameContext {
    const GpuScene& scene;
    const Camera& camera;
    glm::mat4 view;
    glm::mat4 projection;
    glm::mat4 viewProjection;
    glm::ivec2 size;
    const FrameTargets& targets;
    gl::GpuTimer* timer;                  // null when not timing
    std::vector<int> transparentOrder;    // submission order of transparent objects
    // What draws in each object's place this frame (render/stand_in.hpp); null: every object
    // draws its own triangles.
    const StandIns* standIns = nullptr;
    // Every pixel a transparent object can draw to this frame (the union of their bounding
    // spheres on screen; FrameRenderer sets it). A full-screen pass that changes nothing where no
    // transparent fragment lies is scissored to it (TransparentAreaScissor). Unset: the whole frame.
    std::optional<PixelRect> transparentArea;

    // What draws in `object`'s place this frame, or null (its own triangles).
    const StandInDraw* standInOf(int object) const { return standIns ? (*standIns)[std::size_t(object)] : nullptr; }
    // Where what `object` draws lies: a LOD unit's stand-in holds all the unit's parts, so every
    // pass that bounds an object (culling, sorting, object skipping, bucket ranges) takes these.
    const Bounds& boundsOf(int object) const {
        const StandInDraw* s = standInOf(object);
        return s && !s->worldBounds.empty() ? s->worldBounds : scene.objects()[std::size_t(object)].worldBounds;
    }

    // Draws `object` (or its stand-in) with `program`, which must be bound: every pass draws
    // scene objects through this, so a stand-in reaches every technique.
    void draw(const SceneProgram& program, int object) const { scene.draw(program, object, standInOf(object)); }
    // Draws `order` the same way, objects that share a mesh instanced together
    // (GpuScene::drawObjects); returns the GL draws issued.
    std::size_t drawAll(const SceneProgram& program, const std::vector<int>& order) const {
        return scene.drawObjects(program, order, standIns);
    }
};

class Technique {
public:
    explicit Technique(TechniqueInfo info) : info_(std::move(info)) {}
    virtual ~Technique() = default;
    const TechniqueInfo& info() const { return info_; }
    virtual void render(const FrameContext& frame) = 0;
    const TechniqueStats& stats() const { return stats_; }

    // The settings, described once per technique (see settings.hpp). setSettings takes values
    // already checked against the descriptions (resolveSettings, the panel); they apply from the
    // next render, which compares them with the previous frame's to reallocate what changed.
    virtual std::vector<SettingDescription> settingDescriptions() const = 0;
    virtual SettingValues settings() const = 0;
    virtual void setSettings(const SettingValues& values) = 0;

protected:
    TechniqueInfo info_;
    TechniqueStats stats_;
};

// A technique whose settings are the plain struct S, described by S::schema().
template <class S>
class TechniqueWithSettings : public Technique {
public:
    using Settings = S;
    using Technique::Technique;
    std::vector<SettingDescription> settingDescriptions() const override { return S::schema().descriptions(); }
    SettingValues settings() const override { return S::schema().read(settings_); }
    void setSettings(const SettingValues& values) override { settings_ = S::schema().write(values); }

protected:
    S settings_;
};

struct TechniqueEntry {
    TechniqueInfo info;
    std::vector<SettingDescription> settings;  // readable without a GL context
    std::function<std::unique_ptr<Technique>()> create;
};

// The registry line of technique class T, constructed from its info and `args`.
template <class T, class... Args>
TechniqueEntry techniqueEntry(TechniqueInfo info, Args... args) {
    return {info, T::Settings::schema().descriptions(), [info, args...] { return std::make_unique<T>(info, args...); }};
}

// Every technique by id, in display order. The command line, panel and bench read this list.
const std::vector<TechniqueEntry>& techniqueRegistry();
// Throws std::invalid_argument listing the known ids when `id` is unknown.
std::unique_ptr<Technique> createTechnique(const std::string& id);
const TechniqueEntry* findTechnique(const std::string& id);

}  // namespace strata

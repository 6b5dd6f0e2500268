// The per-frame LOD step (lod/lod_controller.hpp) on builtin:field:4: forced impostors stand in
// for every instance but not for the ground the eye is over, an eye inside an instance's bounds
// gets its geometry back, geometry mode bakes nothing, and the stand-ins reach the frame.
#include "gl_test_support.hpp"

#include "frame/frame_renderer.hpp"
#include "lod/lod_controller.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

using namespace strata;
using namespace strata::lod;

namespace {

LodOptions smallImpostors(LodMode mode) {
    LodOptions o;
    o.mode = mode;
    o.impostor.views = 12;
    o.impostor.resolution = 32;
    o.impostor.slices = 8;
    return o;
}

int standInCount(const StandIns* s) {
    int n = 0;
    if (s)
        for (const StandInDraw* d : *s) n += d ? 1 : 0;
    return n;
}

}  // namespace

TEST_CASE("lod controller: forced impostors stand in for the four instances, not the ground") {
    test::Fixture fx(makeFieldScene(4, false));
    REQUIRE(fx.gpu->objects().size() == 5);
    LodController lod(*fx.gpu, smallImpostors(LodMode::Impostors));
    const StandIns* s = lod.select(fx.camera, {64, 48});
    REQUIRE(s);
    CHECK(standInCount(s) == 4);
    CHECK(lod.selection().impostorObjects == 4);
    CHECK(lod.selection().impostorsUsed == 1);  // one mesh, one impostor
    REQUIRE(lod.impostors());
    CHECK(lod.selection().impostorBytes == lod.impostors()->impostorOfMesh(fx.gpu->objects()[1].mesh)->bytes().total());
    // The ground: the eye is within two of its radii, so geometry whatever the mode.
    int ground = -1;
    for (int i = 0; i < 5; ++i)
        if (fx.gpu->scene().meshes[std::size_t(fx.gpu->objects()[std::size_t(i)].mesh)].triangleCount() < 100) ground = i;
    REQUIRE(ground >= 0);
    CHECK((*s)[std::size_t(ground)] == nullptr);
    const LodReason why = lod.selection().objects[std::size_t(ground)].reason;
    CHECK((why == LodReason::EyeInside || why == LodReason::TooClose));

    // Drawn through the frame: the stand-ins render, finite, with no GL error.
    FrameRenderer renderer;
    FrameOptions options;
    options.standIns = s;
    renderer.render(*fx.gpu, fx.camera, {64, 48}, nullptr, options);
    gl::checkGl("impostor frame");
}

TEST_CASE("lod controller: the eye inside an instance's bounds gets its geometry") {
    test::Fixture fx(makeFieldScene(4, false));
    LodController lod(*fx.gpu, smallImpostors(LodMode::Impostors));
    Camera inside = fx.camera;
    inside.position = fx.gpu->objects()[1].worldBounds.center();
    const StandIns* s = lod.select(inside, {64, 48});
    CHECK(lod.selection().objects[1].reason == LodReason::EyeInside);
    CHECK(!lod.selection().objects[1].impostor);
    if (s) CHECK((*s)[1] == nullptr);
}

TEST_CASE("lod controller: geometry bakes and measures nothing") {
    test::Fixture fx(makeFieldScene(4, false));
    LodController lod(*fx.gpu, smallImpostors(LodMode::Geometry));
    CHECK(lod.select(fx.camera, {64, 48}) == nullptr);
    CHECK(lod.impostors() == nullptr);
    CHECK(!lod.calibration());
    CHECK(lod.selection().impostorObjects == 0);
}

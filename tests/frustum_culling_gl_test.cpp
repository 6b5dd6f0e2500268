// View-frustum culling (render/frustum.hpp, FrameOptions::cull): on a known view the objects
// outside are counted and drawn by no pass, and every image equals the unculled one bit for bit.
#include "material_test_scenes.hpp"

#include "render/frustum.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace strata;
using namespace strata::test::material;

namespace {

// framedScene's view (the eye at z = 3 looking down -Z, the backdrop at z = -1) with one
// transparent quad in view and three objects out of it: a transparent quad behind the eye, one
// far to the left, and an opaque one far to the right.
Scene sceneWithObjectsOutside() {
    Scene s = framedScene();
    addObject(s, quad(-1, 1, 0), blend({0.9f, 0.3f, 0.1f, 0.5f}));     // in view
    addObject(s, quad(-1, 1, 5.0f), blend({0.1f, 0.3f, 0.9f, 0.5f}));  // behind the eye
    addObject(s, quad(-61, -59, 0), blend({0.1f, 0.9f, 0.3f, 0.5f}));  // far left
    Material opaque;
    opaque.baseColor = glm::vec3(0.5f);
    addObject(s, quad(59, 61, 0), opaque);  // far right
    return s;
}

}  // namespace

TEST_CASE("frustum: a sphere is culled only wholly outside one plane") {
    const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(60.0f), 1.0f, 1.0f, 100.0f);
    const Frustum f(projection);  // the eye at the origin looking down -Z
    auto box = [](glm::vec3 c, float half) {
        Bounds b;
        b.extend(c - glm::vec3(half));
        b.extend(c + glm::vec3(half));
        return b;
    };
    CHECK(f.mayContain(box({0, 0, -10}, 1)));
    CHECK_FALSE(f.mayContain(box({0, 0, 10}, 1)));      // behind the eye
    CHECK_FALSE(f.mayContain(box({0, 0, -200}, 1)));    // past the far plane
    CHECK_FALSE(f.mayContain(box({50, 0, -10}, 1)));    // right of the view
    // Straddling the right plane (x = tan 30 deg * 10 = 5.77 at z = -10): kept.
    CHECK(f.mayContain(box({6.5f, 0, -10}, 1)));
    CHECK_FALSE(f.mayContain(Bounds{}));                 // no geometry
}

TEST_CASE("frustum culling: objects out of view are counted and drawn by no pass; images unchanged") {
    test::glContext();
    GpuScene scene(sceneWithObjectsOutside());
    const Camera camera = defaultCamera(scene.scene(), scene.objects());
    for (const std::string id : {"abuffer", "f2b", "dual-2p", "wboit", "blend-sorted"}) {
        CAPTURE(id);
        FrameOptions off;
        off.cull = false;
        const test::Rendered all = test::renderWith(scene, camera, kSize, id, off);
        const test::Rendered culled = test::renderWith(scene, camera, kSize, id);
        CHECK(all.result.objectsCulled == 0);
        CHECK(culled.result.objectsCulled == 3);
        CHECK(culled.image.rgba == all.image.rgba);
        // One transparent object drawn per geometry pass instead of three.
        CHECK(culled.result.stats.objectDraws * 3 == all.result.stats.objectDraws);
    }
}

TEST_CASE("frustum culling: with every transparent object out of view no transparency pass runs") {
    test::glContext();
    Scene s = framedScene();
    addObject(s, quad(-1, 1, 5.0f), blend({0.1f, 0.3f, 0.9f, 0.5f}));  // behind the eye
    GpuScene scene(std::move(s));
    const Camera camera = defaultCamera(framedScene(), flatten(framedScene()));
    FrameOptions off;
    off.cull = false;
    const test::Rendered all = test::renderWith(scene, camera, kSize, "abuffer", off);
    const test::Rendered culled = test::renderWith(scene, camera, kSize, "abuffer");
    CHECK(culled.result.objectsCulled == 1);
    CHECK_FALSE(culled.result.transparencyPass);
    CHECK(culled.image.rgba == all.image.rgba);
}

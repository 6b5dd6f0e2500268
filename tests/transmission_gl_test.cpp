// KHR_materials_transmission through every exact technique: glass behind coloured glass.
//  - Analytic: the same two filters over a white and over a black unlit backdrop; the difference
//    of the two images is what passes through both, per channel: the product of the filters
//    (common/shading_model.h's transmissionFilter, base colour x (1 - Fresnel)) on every exact
//    technique (all composite RGB transmittance), whatever light the glass reflects; blend-sorted
//    too (one pane behind the other, in order).
//  - Against the CPU ray-cast reference, a BLEND decal in front of lit coloured glass on the RGB
//    techniques, and neutral (grey) glass, where the scalar form is exact, on every technique.
// Within 2/255, in the 16 x 16 framed view of material_test_scenes.hpp.
#include "material_test_scenes.hpp"

#include "reference/raycast.hpp"
#include "scene/builtin_scenes.hpp"

#include <glm/gtc/packing.hpp>

#include <doctest/doctest.h>

#include <cmath>

using namespace strata;
using namespace strata::test::material;

namespace {

Material glass(glm::vec3 tint, float transmission, float roughness) {
    Material m;
    m.name = "glass";
    m.baseColor = tint;
    m.transmission = transmission;
    m.roughness = roughness;
    return m;  // OPAQUE: glass is transparent through its transmission, not its alpha
}

const glm::vec3 kFrontTint(1.0f, 0.5f, 0.25f);
const glm::vec3 kBackTint(0.25f, 1.0f, 0.5f);

// Two full-view panes of glass at z = 0.3 and z = 0 over an unlit backdrop of `backdrop`.
Scene twoPanes(glm::vec3 backdrop, glm::vec3 front, glm::vec3 back) {
    Scene s = framedScene();
    s.materials[1].baseColor = backdrop;  // framedScene's backdrop material
    s.materials[1].unlit = true;
    addObject(s, quad(-1, 1, 0.3f), glass(front, 1.0f, 0.5f));
    addObject(s, quad(-1, 1, 0.0f), glass(back, 1.0f, 0.5f));
    return s;
}

glm::vec3 centre(const Image& image) { return glm::vec3(image.at(kSize.x / 2, kSize.y / 2)); }

float mean(glm::vec3 v) { return (v.r + v.g + v.b) / 3.0f; }

bool rgbOnly(const TechniqueInfo& info) { return info.rgbTransmittance; }

}  // namespace

TEST_CASE("glass behind coloured glass: the RGB techniques pass the product of the filters per channel") {
    test::glContext();
    GpuScene white(twoPanes(glm::vec3(1.0f), kFrontTint, kBackTint));
    GpuScene black(twoPanes(glm::vec3(0.0f), kFrontTint, kBackTint));
    REQUIRE(white.hasColoredFilters());
    const std::vector<Object> objects = flatten(white.scene());
    const Camera camera = defaultCamera(white.scene(), objects);
    // The centre pixel is seen within 1.3 degrees of the normal: Fresnel is F0 there (to 1e-15).
    const glm::vec3 front = gpu::transmissionFilter(kFrontTint, 0.0f, 1.0f, gpu::kDefaultIor, 1.0f);
    const glm::vec3 back = gpu::transmissionFilter(kBackTint, 0.0f, 1.0f, gpu::kDefaultIor, 1.0f);
    CHECK(front.r == doctest::Approx(0.96f));
    const glm::vec3 want = front * back;  // (0.230, 0.461, 0.115); the scalar forms': 0.3136 in each
    CHECK(std::abs(want.g - mean(front) * mean(back)) > 0.1f);
    // bun is exact here too: two fragments a pixel in eight buckets; blend-sorted, two objects
    // drawn back to front.
    std::vector<std::string> ids = exactIds();
    ids.push_back("bun");
    ids.push_back("blend-sorted");
    // abuffer, ll, fab, kbuffer, sbuffer, bun-ll, f2b, f2b2, dual, the coplanarity-aware f2b-2p,
    // f2b-3p, dual-2p, f2b-ll, f2b-fab, f2b-kb, dual-ll, dual-fab; abuffer-volume, ll-volume;
    // bun, blend-sorted.
    CHECK(ids.size() == 21);
    for (const std::string& id : ids) {
        CAPTURE(id);
        auto t = exactTechnique(id);
        CHECK(t->info().rgbTransmittance);
        const glm::vec3 through = centre(test::renderWith(white, camera, kSize, *t).image) -
                                  centre(test::renderWith(black, camera, kSize, *t).image);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(through[c] - want[c]) <= kTolerance);
    }
}

TEST_CASE("a BLEND decal over lit coloured glass behind glass matches the reference on the RGB techniques") {
    test::glContext();
    Scene s = framedScene();
    s.lightDirection = glm::normalize(glm::vec3(0.4f, 0.5f, 1.0f));
    addObject(s, quad(-1, 0, 0.5f), blend({0.2f, 0.4f, 1.0f, 0.5f}));
    addObject(s, quad(-1, 1, 0.3f), glass(kFrontTint, 1.0f, 0.3f));
    addObject(s, quad(-0.5f, 1, 0.0f), glass(kBackTint, 0.7f, 0.6f));
    checkAgainstReference(std::move(s), rgbOnly);
}

TEST_CASE("neutral glass composites exactly on every exact technique, in its scalar form too") {
    test::glContext();
    Scene s = framedScene();
    s.lightDirection = glm::normalize(glm::vec3(0.4f, 0.5f, 1.0f));
    addObject(s, quad(-1, 0, 0.5f), blend({0.2f, 0.4f, 1.0f, 0.5f}));
    addObject(s, quad(-1, 1, 0.3f), glass(glm::vec3(0.8f), 1.0f, 0.3f));
    addObject(s, quad(-0.5f, 1, 0.0f), glass(glm::vec3(0.5f), 0.6f, 0.6f));
    checkAgainstReference(std::move(s));
}

TEST_CASE("every technique draws coloured glass: each build of the transmission variant compiles, output finite") {
    test::glContext();
    GpuScene white(twoPanes(glm::vec3(1.0f), kFrontTint, kBackTint));
    const std::vector<Object> objects = flatten(white.scene());
    const Camera camera = defaultCamera(white.scene(), objects);
    for (const auto& e : techniqueRegistry()) {
        CAPTURE(e.info.id);
        auto t = createTechnique(e.info.id);
        const glm::vec3 c = centre(test::renderWith(white, camera, kSize, *t).image);
        for (int k = 0; k < 3; ++k) {
            CHECK(std::isfinite(c[k]));
            CHECK(c[k] >= 0.0f);
            CHECK(c[k] <= 1.5f);
        }
    }
}

TEST_CASE("coplanar coloured glass: the coplanarity-aware RGB techniques composite it in the tie order") {
    // Two panes of differently tinted glass and a BLEND decal in one plane, over a third pane
    // behind: the coplanar three filter and reflect in (object, primitive) order, which the
    // colours added show (glass reflects, so the order is visible although the filters commute).
    test::glContext();
    Scene s = framedScene();
    s.lightDirection = glm::normalize(glm::vec3(0.4f, 0.5f, 1.0f));
    addObject(s, quad(-1, 1, 0.3f), glass(kFrontTint, 1.0f, 0.3f));
    addObject(s, quad(-1, 1, 0.3f), glass(kBackTint, 0.8f, 0.5f));
    addObject(s, quad(-0.5f, 1, 0.3f), blend({0.2f, 0.4f, 1.0f, 0.5f}));
    addObject(s, quad(-1, 1, 0.0f), glass(glm::vec3(0.6f, 0.6f, 1.0f), 1.0f, 0.4f));
    checkAgainstReference(std::move(s),
                          [](const TechniqueInfo& info) { return info.rgbTransmittance && info.handlesCoplanarity; });
}

TEST_CASE("six panes of coloured glass: every RGB technique equals the reference, peeling over several passes") {
    checkAgainstReference(makeLitLayersScene(6, true), rgbOnly, 8);
}

TEST_CASE("in a scene with glass, the buffers keep every other fragment at the scalar layout's precision") {
    // Sixteen black BLEND layers of alpha 0.05 over a white unlit backdrop, and a small pane of
    // glass in a corner, which makes the scene's buffers store coloured filters. The centre sees
    // the layers only: white x (1 - a)^16 with a as a half stores it (0.4402). A 10-bit
    // transmittance would give 0.4412 there (0.95 rounds to 972 / 1023).
    test::glContext();
    Scene s = framedScene();
    s.materials[1].baseColor = glm::vec3(1.0f);
    s.materials[1].unlit = true;
    for (int i = 0; i < 16; ++i) {
        Material layer = blend({0.0f, 0.0f, 0.0f, 0.05f});
        layer.unlit = true;
        addObject(s, quad(-1, 1, 0.5f - 0.05f * float(i)), layer);
    }
    Mesh corner = quad(0.8f, 1.0f, 0.6f);
    addObject(s, std::move(corner), glass(kFrontTint, 1.0f, 0.5f));
    const std::vector<Object> objects = flatten(s);
    const Camera camera = defaultCamera(s, objects);
    GpuScene gpu(std::move(s));
    REQUIRE(gpu.hasColoredFilters());
    const float a = glm::unpackHalf1x16(glm::packHalf1x16(0.05f));
    const float want = std::pow(1.0f - a, 16.0f);
    for (const std::string id : {"abuffer", "ll", "sbuffer", "bun-ll"}) {
        CAPTURE(id);
        auto t = createTechnique(id);
        if (test::hasSetting(id, "capacity")) test::setSetting(*t, "capacity=20");
        const glm::vec3 c = centre(test::renderWith(gpu, camera, kSize, *t).image);
        CHECK(std::abs(c.g - want) <= 2e-5f);
    }
}

// glTF material features against the same colours stated with factors alone: a textured BLEND
// quad whose halves have alphas a1 and a2 against two factor quads, MASK against the cut
// geometry, a constant COLOR_0 against the factor, a texture transform offset against the
// swapped texture. Each pair through every exact technique and the CPU ray-cast reference,
// within 2/255.
//
// The view is set up so that filtering cannot matter: the quad fills a 16 x 16 view exactly, a
// 2 x 1 texture with NEAREST filtering puts its texel boundary at x = 0, and pixel centres lie
// 1/16 of the quad's width from it. The GPU samples level 0 there (the texels are magnified), as
// the CPU reference does.
#include "material_test_scenes.hpp"

#include "reference/raycast.hpp"
#include "render/shading.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/texture_sampling.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

using namespace strata;
using namespace strata::test::material;

namespace {

// A framed scene holding the two-texel image, and a white BLEND material reading it with NEAREST.
Scene sceneWithTexels(glm::u8vec4 left, glm::u8vec4 right) {
    Scene s = framedScene();
    s.images.push_back(twoTexels(left, right));
    return s;
}

Material texturedBlend(TextureWrap wrap = TextureWrap::ClampToEdge) {
    Material m = blend({1.0f, 1.0f, 1.0f, 1.0f});
    m.baseColorTexture.image = 0;
    m.baseColorTexture.sampler = nearestSampler(wrap);
    return m;
}

// What a quad over [-1, 1] textured with (left, right) should look like: two factor quads.
Scene factorHalves(glm::u8vec4 left, glm::u8vec4 right) {
    Scene s = framedScene();
    addObject(s, quad(-1, 0, 0), blend(linearTexel(left)));
    addObject(s, quad(0, 1, 0), blend(linearTexel(right)));
    return s;
}

// `textured` and `factors` render alike on the CPU reference and on every exact technique, and
// each GPU image matches the CPU reference of its own scene.
void checkPair(Scene textured, Scene factors) {
    test::glContext();
    const std::vector<Object> texturedObjects = flatten(textured), factorObjects = flatten(factors);
    const Camera camera = defaultCamera(textured, texturedObjects);
    const Image cpuTextured = raycastReference(textured, texturedObjects, camera, kSize.x, kSize.y);
    const Image cpuFactors = raycastReference(factors, factorObjects, camera, kSize.x, kSize.y);
    CHECK(compareImages(cpuTextured, cpuFactors).maxAbsError <= kTolerance);

    GpuScene gpuTextured(std::move(textured)), gpuFactors(std::move(factors));
    for (const std::string& id : exactIds()) {
        CAPTURE(id);
        auto a = exactTechnique(id);
        auto b = exactTechnique(id);
        test::Rendered t = test::renderWith(gpuTextured, camera, kSize, *a);
        test::Rendered f = test::renderWith(gpuFactors, camera, kSize, *b);
        CHECK(compareImages(t.image, cpuTextured).maxAbsError <= kTolerance);
        CHECK(compareImages(f.image, cpuFactors).maxAbsError <= kTolerance);
        CHECK_FALSE(t.result.stats.overflowed);
    }
}

}  // namespace

TEST_CASE("a BLEND quad textured with alphas a1 and a2 equals two factor quads") {
    const glm::u8vec4 left(230, 40, 40, 64), right(40, 200, 90, 191);  // a1 = 0.25, a2 = 0.75
    Scene textured = sceneWithTexels(left, right);
    addObject(textured, quad(-1, 1, 0), texturedBlend());
    Scene factors = factorHalves(left, right);

    // The expected colour, stated: texel over the lit backdrop, both facing the light alike.
    const std::vector<Object> objects = flatten(factors);
    const Camera camera = defaultCamera(factors, objects);
    // Both lit by the shading model along the pixel's ray, facing +z.
    glm::dvec3 origin, direction;
    pixelRay(camera, kSize.x, kSize.y, 3, 8, origin, direction);
    auto lit = [&](glm::vec3 base) {
        return shadeSurface(base, 0.0f, 1.0f, 1.0f, glm::vec3(0.0f), {0, 0, 1}, glm::vec3(-glm::normalize(direction)),
                            factors.lightDirection, glm::vec3(kDefaultLightIrradiance));
    };
    const glm::vec4 l = linearTexel(left);
    const glm::vec3 want = lit(glm::vec3(l)) * l.a + lit({0.2f, 0.3f, 0.4f}) * (1.0f - l.a);
    const glm::vec4 got = raycastReference(textured, flatten(textured), camera, kSize.x, kSize.y).at(3, 8);
    CHECK(std::abs(got.r - want.r) <= 1e-4f);
    CHECK(std::abs(got.g - want.g) <= 1e-4f);
    CHECK(std::abs(got.b - want.b) <= 1e-4f);

    checkPair(std::move(textured), std::move(factors));
}

TEST_CASE("screendoor-object-sw keeps its points by the texture's alpha and tints them by its colour") {
    // The textured quad of the test above against its two factor quads, through the point
    // sampling technique at 16 x 16 supersampling: each half's mean colour is the same within
    // the sampling noise. A half holds 8 x 16 pixels of 256 samples (32768), each point kept
    // with probability a: the mean's variance is at most 0.25 / 32768 per image, so the two
    // images' means differ by at most 5 standard deviations of the difference, 0.0138 per unit
    // of the covered-uncovered contrast (at most 1 here), unless the alpha or tint is lost
    // (alpha 1 instead of 0.25 moves the left half by about 0.4).
    test::glContext();
    const glm::u8vec4 left(230, 40, 40, 64), right(40, 200, 90, 191);
    Scene textured = sceneWithTexels(left, right);
    addObject(textured, quad(-1, 1, 0), texturedBlend());
    Scene factors = factorHalves(left, right);
    const Camera camera = defaultCamera(factors, flatten(factors));
    GpuScene gpuTextured(std::move(textured)), gpuFactors(std::move(factors));
    auto render = [&](const GpuScene& scene) {
        auto t = test::makeTechnique("screendoor-object-sw", {"supersampling=16"});
        test::Rendered r = test::renderWith(scene, camera, kSize, *t);
        CHECK_FALSE(r.result.stats.overflowed);
        return r.image;
    };
    const Image t = render(gpuTextured), f = render(gpuFactors);
    const double tolerance = 5.0 * std::sqrt(2.0 * 0.25 / (8.0 * 16.0 * 256.0));
    for (int half = 0; half < 2; ++half) {
        glm::dvec3 sumT(0.0), sumF(0.0);
        for (int y = 0; y < kSize.y; ++y)
            for (int x = half * 8; x < half * 8 + 8; ++x) {
                sumT += glm::dvec3(glm::vec3(t.at(x, y)));
                sumF += glm::dvec3(glm::vec3(f.at(x, y)));
            }
        const glm::dvec3 meanT = sumT / 128.0, meanF = sumF / 128.0;
        CAPTURE(half);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(meanT[c] - meanF[c]) <= tolerance);
    }
}

TEST_CASE("a MASK texture cuts like the cut geometry, in the opaque pass and the reference") {
    const glm::u8vec4 kept(200, 180, 60, 255), cut(20, 20, 200, 51);  // alpha 1 and 0.2
    Scene textured = sceneWithTexels(kept, cut);
    Material m;
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.5f;
    m.baseColor = glm::vec3(1.0f);
    m.baseColorTexture.image = 0;
    m.baseColorTexture.sampler = nearestSampler();
    addObject(textured, quad(-1, 1, 0), m);
    // A transparent quad in front, so the transparency techniques run over the cut-out.
    addObject(textured, quad(-1, 1, 0.5f), blend({0.9f, 0.9f, 0.9f, 0.3f}));

    Scene factors = framedScene();
    Material opaque;
    opaque.baseColor = glm::vec3(linearTexel(kept));
    addObject(factors, quad(-1, 0, 0), opaque);
    addObject(factors, quad(-1, 1, 0.5f), blend({0.9f, 0.9f, 0.9f, 0.3f}));
    checkPair(std::move(textured), std::move(factors));
}

TEST_CASE("a constant COLOR_0 equals the same colour as the factor") {
    const glm::vec4 color(0.7f, 0.25f, 0.5f, 0.6f);
    Scene colored = framedScene();
    Mesh mesh = quad(-1, 1, 0);
    mesh.colors.assign(mesh.positions.size(), color);
    addObject(colored, mesh, blend({1.0f, 1.0f, 1.0f, 1.0f}));
    Scene factors = framedScene();
    addObject(factors, quad(-1, 1, 0), blend(color));
    checkPair(std::move(colored), std::move(factors));
}

TEST_CASE("a texture transform offset of half the texture equals the swapped texture") {
    const glm::u8vec4 a(250, 120, 30, 128), b(30, 90, 250, 220);
    Scene shifted = sceneWithTexels(a, b);
    Material m = texturedBlend(TextureWrap::Repeat);
    m.baseColorTexture.transform.offset = {0.5f, 0.0f};
    addObject(shifted, quad(-1, 1, 0), m);

    Scene swapped = sceneWithTexels(b, a);
    addObject(swapped, quad(-1, 1, 0), texturedBlend());
    checkPair(std::move(shifted), std::move(swapped));
}

TEST_CASE("TEXCOORD_1 is used when the texture names it") {
    const glm::u8vec4 a(250, 250, 30, 100), b(30, 200, 250, 240);
    Scene second = sceneWithTexels(a, b);
    Material m = texturedBlend();
    m.baseColorTexture.texCoord = 1;
    Mesh mesh = quad(-1, 1, 0);
    mesh.texCoords[1] = mesh.texCoords[0];
    for (auto& uv : mesh.texCoords[0]) uv = {0.9f, 0.5f};  // set 0 would give texel b everywhere
    addObject(second, mesh, m);
    checkPair(std::move(second), factorHalves(a, b));
}

TEST_CASE("a mesh placed by three objects is uploaded once: the scene counts it and its bytes once") {
    test::glContext();
    Scene s = framedScene();
    const std::size_t before = s.meshes.size();
    Mesh m = quad(-1, 1, 0);  // 4 vertices with TEXCOORD_0, 6 indices
    const int mesh = s.addMesh(std::move(m));
    for (int i = 0; i < 3; ++i) {
        Node n;
        n.meshes = {mesh};
        n.local = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -float(i)));
        s.addNode(std::move(n));
    }
    const std::size_t frameTriangles = flatten(framedScene()).size() * 2;  // framedScene's backdrop quad(s)
    GpuScene scene(std::move(s));
    CHECK(scene.meshCount() == before + 1);
    CHECK(scene.triangleCount() == frameTriangles + 3 * 2);
    CHECK(scene.meshTriangleCount() == frameTriangles + 2);
    // The shared quad: 4 x 24-byte vertices + 6 x 4-byte indices + 4 x 8-byte coordinates.
    GpuScene frameOnly(framedScene());
    CHECK(scene.meshBytes() - frameOnly.meshBytes() == 4 * 24 + 6 * 4 + 4 * 8);
}

TEST_CASE("a factor-only scene draws with the plain programs: no material variant is built") {
    test::glContext();
    Scene s = framedScene();
    addObject(s, quad(-1, 1, 0), blend({0.5f, 0.5f, 0.5f, 0.5f}));
    GpuScene scene(std::move(s));
    for (std::size_t i = 0; i < scene.objects().size(); ++i) CHECK(scene.materialFeatures(int(i)) == 0u);
    CHECK(scene.textureBytes() == 0);
}

TEST_CASE("texture sampling on the CPU follows the GL wrap modes and filters") {
    TextureImage image = twoTexels({0, 0, 0, 0}, {255, 255, 255, 255});
    Sampler s = nearestSampler(TextureWrap::Repeat);
    CHECK(sampleTexture(image, s, {0.25f, 0.5f}).a == doctest::Approx(0.0f));
    CHECK(sampleTexture(image, s, {0.75f, 0.5f}).a == doctest::Approx(1.0f));
    CHECK(sampleTexture(image, s, {1.25f, 0.5f}).a == doctest::Approx(0.0f));   // repeat
    CHECK(sampleTexture(image, s, {-0.25f, 0.5f}).a == doctest::Approx(1.0f));  // repeat below 0
    s.wrapS = TextureWrap::MirroredRepeat;
    CHECK(sampleTexture(image, s, {1.25f, 0.5f}).a == doctest::Approx(1.0f));   // mirrored: texel 1
    CHECK(sampleTexture(image, s, {1.75f, 0.5f}).a == doctest::Approx(0.0f));
    s.wrapS = TextureWrap::ClampToEdge;
    CHECK(sampleTexture(image, s, {7.0f, 0.5f}).a == doctest::Approx(1.0f));
    CHECK(sampleTexture(image, s, {-7.0f, 0.5f}).a == doctest::Approx(0.0f));
    s.magFilter = TextureFilter::Linear;
    CHECK(sampleTexture(image, s, {0.5f, 0.5f}).a == doctest::Approx(0.5f));   // halfway between centres
    CHECK(sampleTexture(image, s, {0.25f, 0.5f}).a == doctest::Approx(0.0f));  // a texel centre
    // sRGB: 255 decodes to 1, 0 to 0, and the midpoint of a linear blend is in linear space.
    CHECK(sampleTexture(image, s, {0.5f, 0.5f}).r == doctest::Approx(0.5f));
    // Non-finite coordinates give transparent black rather than undefined behaviour.
    CHECK(sampleTexture(image, s, {NAN, 0.5f}).a == 0.0f);
}

TEST_CASE("KHR_texture_transform: offset, rotation and scale compose as T * R * S") {
    TextureTransform t;
    t.offset = {0.5f, 0.25f};
    t.scale = {2.0f, 3.0f};
    t.rotation = float(3.14159265358979323846 / 2.0);
    // S takes (1, 0) to (2, 0); R (a quarter turn, counter-clockwise with v down) to (0, -2);
    // T to (0.5, -1.75).
    const glm::vec2 uv = transformTexCoord(t.matrix(), {1.0f, 0.0f});
    CHECK(uv.x == doctest::Approx(0.5f).epsilon(1e-5));
    CHECK(uv.y == doctest::Approx(-1.75f).epsilon(1e-5));
    CHECK(TextureTransform{}.identity());
}

TEST_CASE("builtin:layers:N:textured draws through a white texture and equals builtin:layers:N") {
    test::glContext();
    GpuScene textured(makeBuiltinScene("layers:5:textured")), plain(makeBuiltinScene("layers:5"));
    REQUIRE(textured.objects().size() == 5);
    CHECK((textured.materialFeatures(0) & kSceneBaseColorTexture) != 0u);
    CHECK(textured.textureBytes() == 64 * 64 * 4 * 4 / 3);
    const Camera camera = defaultCamera(plain.scene(), plain.objects());
    for (const std::string id : {"abuffer", "f2b", "wboit", "blend-sorted"}) {
        CAPTURE(id);
        const Image a = test::renderWith(textured, camera, {12, 10}, id).image;
        const Image b = test::renderWith(plain, camera, {12, 10}, id).image;
        CHECK(compareImages(a, b).maxAbsError <= 1.0f / 255.0f);
    }
    CHECK_THROWS_AS(makeBuiltinScene("layers:5:shiny"), std::invalid_argument);
}

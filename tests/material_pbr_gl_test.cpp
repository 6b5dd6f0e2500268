// The metallic-roughness material (glTF 3.9, appendix B) through every exact technique, against
// the CPU ray-cast reference, which shades with the same header (common/shading_model.h), and
// each texture against the same values stated as factors: a metallic-roughness texture whose
// halves are a rough dielectric and a smooth metal against two factor quads, an emissive
// texture against emissive factors, a normal texture against the normal it encodes given as
// vertex normals. Within 2/255, in the 16 x 16 framed view of material_test_scenes.hpp (NEAREST
// textures, magnified: filtering cannot matter).
#include "material_test_scenes.hpp"

#include "reference/raycast.hpp"
#include "scene/tangents.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <doctest/doctest.h>

using namespace strata;
using namespace strata::test::material;

namespace {

// Two linear texels (metallic-roughness, normal and occlusion textures are not sRGB).
TextureImage linearTexels(glm::u8vec4 left, glm::u8vec4 right) { return twoTexels(left, right); }

// `a` and `b` render alike on the CPU reference, and each GPU image matches its reference.
void checkPair(Scene a, Scene b) {
    const Image ia = checkAgainstReference(std::move(a));
    const Image ib = checkAgainstReference(std::move(b));
    CHECK(compareImages(ia, ib).maxAbsError <= kTolerance);
}

Material pbrBlend(glm::vec4 factor, float metallic, float roughness) {
    Material m = blend(factor);
    m.metallic = metallic;
    m.roughness = roughness;
    return m;
}

// The light comes from the upper right and the eye is at (0, 0, 3): the quads show a highlight
// and a falloff, not one flat value.
Scene litScene() {
    Scene s = framedScene();
    s.lightDirection = glm::normalize(glm::vec3(0.4f, 0.5f, 1.0f));
    return s;
}

}  // namespace

TEST_CASE("metallic and roughness factors shade alike on every exact technique and the reference") {
    const glm::vec4 gold(1.0f, 0.77f, 0.34f, 0.6f);
    Scene metal = litScene();
    addObject(metal, quad(-1, 1, 0), pbrBlend(gold, 1.0f, 0.35f));
    const Image metalImage = checkAgainstReference(metal);
    Scene dielectric = litScene();
    addObject(dielectric, quad(-1, 1, 0), pbrBlend(gold, 0.0f, 0.35f));
    const Image dielectricImage = checkAgainstReference(dielectric);
    // Not one shading model under two names: a metal has no diffuse term and a coloured
    // highlight, so the images differ far beyond the tolerance.
    CHECK(compareImages(metalImage, dielectricImage).maxAbsError > 0.05f);
}

TEST_CASE("a metallic-roughness texture equals its texels given as factors") {
    // Left: roughness 1, metallic 0. Right: roughness 64/255, metallic 1 (green roughness,
    // blue metallic; red unused).
    const glm::u8vec4 rough(0, 255, 0, 255), smoothMetal(0, 64, 255, 255);
    Scene textured = litScene();
    textured.images.push_back(linearTexels(rough, smoothMetal));
    Material m = pbrBlend({0.9f, 0.6f, 0.3f, 0.7f}, 1.0f, 1.0f);
    m.metallicRoughnessTexture.image = 0;
    m.metallicRoughnessTexture.sampler = nearestSampler();
    addObject(textured, quad(-1, 1, 0), m);

    Scene factors = litScene();
    addObject(factors, quad(-1, 0, 0), pbrBlend({0.9f, 0.6f, 0.3f, 0.7f}, 0.0f, 1.0f));
    addObject(factors, quad(0, 1, 0), pbrBlend({0.9f, 0.6f, 0.3f, 0.7f}, 1.0f, 64.0f / 255.0f));
    checkPair(std::move(textured), std::move(factors));
}

TEST_CASE("an emissive texture times its factor equals the product as the factor") {
    const glm::u8vec4 left(255, 128, 0, 255), right(30, 200, 250, 255);
    const glm::vec3 factor(0.5f, 1.0f, 0.8f);
    Scene textured = litScene();
    textured.images.push_back(twoTexels(left, right));
    Material m = pbrBlend({0.2f, 0.2f, 0.2f, 0.5f}, 0.0f, 0.8f);
    m.emissive = factor;
    m.emissiveTexture.image = 0;
    m.emissiveTexture.sampler = nearestSampler();
    addObject(textured, quad(-1, 1, 0), m);

    Scene factors = litScene();
    Material l = pbrBlend({0.2f, 0.2f, 0.2f, 0.5f}, 0.0f, 0.8f), r = l;
    l.emissive = factor * glm::vec3(linearTexel(left));
    r.emissive = factor * glm::vec3(linearTexel(right));
    addObject(factors, quad(-1, 0, 0), l);
    addObject(factors, quad(0, 1, 0), r);
    checkPair(std::move(textured), std::move(factors));
}

TEST_CASE("a normal texture equals the normal it encodes given as vertex normals, tangents derived") {
    // Texels tilting the normal towards +u (right) and towards +Y of the image (up); the quad's
    // u runs along +x and its v down the image, so the derived tangent is +x and the bitangent +y.
    const glm::u8vec4 right(200, 128, 220, 255), up(128, 190, 230, 255);
    Scene mapped = litScene();
    mapped.images.push_back(linearTexels(right, up));
    Material m = pbrBlend({0.8f, 0.8f, 0.8f, 0.8f}, 0.0f, 0.5f);
    m.normalTexture.image = 0;
    m.normalTexture.sampler = nearestSampler();
    addObject(mapped, quad(-1, 1, 0), m);  // no tangents: checkAgainstReference derives them

    auto encoded = [](glm::u8vec4 t) { return glm::normalize(glm::vec3(t) / 255.0f * 2.0f - 1.0f); };
    Scene normals = litScene();
    Mesh left = quad(-1, 0, 0), rightHalf = quad(0, 1, 0);
    left.normals.assign(4, encoded(right));
    rightHalf.normals.assign(4, encoded(up));
    addObject(normals, left, pbrBlend({0.8f, 0.8f, 0.8f, 0.8f}, 0.0f, 0.5f));
    addObject(normals, rightHalf, pbrBlend({0.8f, 0.8f, 0.8f, 0.8f}, 0.0f, 0.5f));
    checkPair(std::move(mapped), std::move(normals));
}

TEST_CASE("an occlusion texture darkens the environment term only, alike on the GPU and the reference") {
    Scene occluded = litScene();
    occluded.images.push_back(linearTexels({64, 0, 0, 255}, {255, 0, 0, 255}));
    Material m = pbrBlend({0.7f, 0.7f, 0.7f, 0.9f}, 0.0f, 0.9f);
    m.occlusionTexture.image = 0;
    m.occlusionTexture.sampler = nearestSampler();
    m.occlusionStrength = 0.5f;
    addObject(occluded, quad(-1, 1, 0), m);
    const Image withOcclusion = checkAgainstReference(occluded);
    Scene open = litScene();
    addObject(open, quad(-1, 1, 0), pbrBlend({0.7f, 0.7f, 0.7f, 0.9f}, 0.0f, 0.9f));
    const Image without = checkAgainstReference(open);
    // The right half's texel is 1: unchanged. The left half loses (1 - occlusion) of the
    // environment term, occlusion = 1 + 0.5 (64/255 - 1), times alpha 0.9 over the backdrop.
    const float lost = (1.0f - gpu::occlusionOf(64.0f / 255.0f, 0.5f)) * 0.9f;
    const glm::vec3 environment = gpu::environmentLight(glm::vec3(0.7f), glm::vec3(gpu::kDielectricF0), 0.9f, 1.0f, 1.0f);
    CHECK(std::abs(withOcclusion.at(12, 8).r - without.at(12, 8).r) <= 1e-5f);
    const float darker = without.at(3, 8).r - withOcclusion.at(3, 8).r;
    // n.v is near 1 at the pixel (the eye is 3 away, the point within 0.6 of the axis).
    CHECK(darker == doctest::Approx(lost * environment.r).epsilon(0.02));
}

TEST_CASE("an unlit material is its base colour on every exact technique") {
    Scene s = litScene();
    Material m = pbrBlend({0.3f, 0.6f, 0.9f, 0.5f}, 1.0f, 0.2f);
    m.unlit = true;
    m.emissive = glm::vec3(1.0f);  // unlit: no light and no emission
    addObject(s, quad(-1, 1, 0), m);
    const Image cpu = checkAgainstReference(s);
    // Over the lit backdrop: 0.5 of the base colour plus 0.5 of the backdrop's shaded colour.
    Scene behind = litScene();
    const Image backdropOnly = raycastReference(behind, flatten(behind), defaultCamera(behind, flatten(behind)),
                                                kSize.x, kSize.y);
    for (int x : {2, 9, 14}) {
        CAPTURE(x);
        const glm::vec4 got = cpu.at(x, 8), under = backdropOnly.at(x, 8);
        CHECK(got.r == doctest::Approx(0.5f * 0.3f + 0.5f * under.r).epsilon(1e-4));
        CHECK(got.b == doctest::Approx(0.5f * 0.9f + 0.5f * under.b).epsilon(1e-4));
    }
}

TEST_CASE("a scene's punctual lights replace the default rig, alike on every exact technique and the reference") {
    Scene s = litScene();
    addObject(s, quad(-1, 1, 0), pbrBlend({0.8f, 0.7f, 0.6f, 0.6f}, 0.2f, 0.4f));
    Light point;
    point.type = Light::Type::Point;
    point.intensity = 6.0f;
    point.color = {1.0f, 0.8f, 0.6f};
    s.lights.push_back(point);
    Light spot;
    spot.type = Light::Type::Spot;
    spot.intensity = 8.0f;
    spot.range = 5.0f;
    spot.innerConeAngle = 0.1f;
    spot.outerConeAngle = 0.5f;
    s.lights.push_back(spot);
    Node pointNode;
    pointNode.local = glm::translate(glm::mat4(1.0f), {-0.6f, 0.4f, 1.0f});
    pointNode.light = 0;
    s.addNode(pointNode);
    Node spotNode;  // above the quad's right half, shining down -Z onto it
    spotNode.local = glm::translate(glm::mat4(1.0f), {0.5f, -0.3f, 1.5f});
    spotNode.light = 1;
    s.addNode(spotNode);
    {
        test::glContext();
        // The light loop is a variant: objects of a scene with lights draw with it, and only they.
        GpuScene lights(s);
        for (std::size_t i = 0; i < lights.objects().size(); ++i)
        {
            CHECK((lights.materialFeatures(int(i)) & kScenePunctualLights) != 0u);
            // Lights are not surface detail: --lod auto may still draw these objects as impostors.
            CHECK((lights.materialFeatures(int(i)) & kSceneSurfaceDetail) == 0u);
        }
    }
    const Image lit = checkAgainstReference(s);
    // The default rig alone looks otherwise: the lights are used, not added to it or ignored.
    Scene rig = s;
    rig.lights.clear();
    const Image rigImage = checkAgainstReference(rig);
    CHECK(compareImages(lit, rigImage).maxAbsError > 0.05f);
}

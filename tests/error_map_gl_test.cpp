// The error view's GPU pass (render/error_map.hpp): an image against itself is exactly 0, a
// known difference gives the RMSE, PSNR and worst pixel worked out by hand (and what
// compareImages, the bench's comparison, says), and the false colour follows its stated rule.
#include "gl_test_support.hpp"

#include "render/error_map.hpp"
#include "render/texture_readback.hpp"
#include "scene/builtin_scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace strata;

namespace {

gl::Texture upload(const Image& image) {
    gl::Texture t = gl::createTexture2D(GL_RGBA32F, image.width, image.height);
    glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.rgba.data());
    return t;
}

Image filled(int w, int h, glm::vec4 c) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.set(x, y, c);
    return image;
}

}  // namespace

TEST_CASE("error map: a technique against itself is exactly 0 on one texture, within round-off on two renders") {
    test::Fixture f(makeBuiltinScene("cubes"));
    const glm::ivec2 size{48, 36};
    FrameRenderer a, b;
    auto ta = test::makeTechnique("abuffer"), tb = test::makeTechnique("abuffer");
    a.render(*f.gpu, f.camera, size, ta.get());
    b.render(*f.gpu, f.camera, size, tb.get());
    ErrorMap map;
    // Two renders: on a GPU the lists arrive in another order, and a list that arrives in depth
    // order is composited front to back where a sorted one is composited back to front
    // (ordered_composite.glsl), so a pixel may differ in its last bit. On an H200 the two
    // differed by 5.96e-8 (one ulp below 1).
    const ErrorMapStats two = map.compare(a.targets().outputColor(), b.targets().outputColor(), size);
    gl::checkGl("error map");
    CHECK(two.maxAbsError <= 1e-6);
    CHECK(two.psnr >= 100.0 - 1e-9);  // PSNR is capped at 100 dB: 1e-6 is far above the cap
    CHECK(two.pixels == std::size_t(48 * 36));
    // One texture against itself: exactly 0, whatever the arithmetic.
    const ErrorMapStats self = map.compare(a.targets().outputColor(), a.targets().outputColor(), size);
    gl::checkGl("error map");
    CHECK(self.rmse == 0.0);
    CHECK(self.maxAbsError == 0.0);
    CHECK(self.psnr == 100.0);
    CHECK(self.pixels == std::size_t(48 * 36));
    // Where nothing differs the view is a dark grey (the reference's luminance, dimmed).
    const Image shown = readRgbaTexture(map.falseColor(), size);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const glm::vec4 c = shown.at(x, y);
            REQUIRE(c.r == c.g);
            REQUIRE(c.g == c.b);
            REQUIRE(c.r >= 0.03f);
            REQUIRE(c.r <= 0.25f + 1e-6f);
        }
}

TEST_CASE("error map: a known difference gives the stated RMSE, PSNR and worst pixel") {
    test::glContext();
    // 64x64 grey; the reference adds 0.5 to red on the bottom 16 rows and 0.75 to green at (37, 50).
    const int w = 64, h = 64;
    Image image = filled(w, h, {0.25f, 0.25f, 0.25f, 1.0f});
    Image reference = image;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < w; ++x) reference.set(x, y, {0.75f, 0.25f, 0.25f, 1.0f});
    reference.set(37, 50, {0.25f, 1.0f, 0.25f, 1.0f});
    // Sum of squares: 16 * 64 * 0.5^2 + 0.75^2 = 256.5625 over 3 * 4096 channels.
    const double rmse = std::sqrt(256.5625 / (3.0 * 4096.0));  // 0.144495...
    const double psnr = 20.0 * std::log10(1.0 / rmse);         // 16.80 dB
    gl::Texture ti = upload(image), tr = upload(reference);
    ErrorMap map;
    const ErrorMapStats s = map.compare(ti.id(), tr.id(), {w, h}, 0.5f);
    gl::checkGl("error map");
    CHECK(s.rmse == doctest::Approx(rmse).epsilon(1e-6));
    CHECK(s.psnr == doctest::Approx(psnr).epsilon(1e-6));
    CHECK(s.psnr == doctest::Approx(16.8039).epsilon(1e-4));
    CHECK(s.maxAbsError == 0.75);
    CHECK(s.worstPixel == glm::ivec2(37, 50));
    // The bench's comparison agrees.
    const ImageDifference cpu = compareImages(image, reference);
    CHECK(s.rmse == doctest::Approx(cpu.rmse).epsilon(1e-6));
    CHECK(s.psnr == doctest::Approx(cpu.psnr).epsilon(1e-6));
    CHECK(s.maxAbsError == doctest::Approx(cpu.maxAbsError));

    // False colour: at or above the scale (0.5) full red; nothing differs above row 15 except one pixel.
    const Image shown = readRgbaTexture(map.falseColor(), {w, h});
    const glm::vec4 red = shown.at(3, 3), worst = shown.at(37, 50), same = shown.at(10, 40);
    CHECK(red.r == doctest::Approx(0.95f));
    CHECK(red.g == doctest::Approx(0.05f));
    CHECK(worst == red);
    CHECK(same.r == same.b);
    CHECK(same.r < 0.25f);

    // Equal maxima: the lowest pixel index wins, whatever the order the groups ran in.
    reference.set(37, 50, {0.25f, 0.25f, 0.25f, 1.0f});
    gl::Texture tr2 = upload(reference);
    const ErrorMapStats tie = map.compare(ti.id(), tr2.id(), {w, h}, 0.5f, false);
    CHECK(tie.maxAbsError == 0.5);
    CHECK(tie.worstPixel == glm::ivec2(0, 0));
    CHECK(tie.rmse == doctest::Approx(std::sqrt(256.0 / (3.0 * 4096.0))).epsilon(1e-6));
}

TEST_CASE("error map: sizes that are not whole groups, and 1x1") {
    test::glContext();
    for (glm::ivec2 size : {glm::ivec2(1, 1), glm::ivec2(13, 7), glm::ivec2(65, 9)}) {
        Image image = filled(size.x, size.y, {0.5f, 0.5f, 0.5f, 1.0f});
        Image reference = image;
        const glm::ivec2 at = size - 1;  // the last pixel, in the last partial group
        reference.set(at.x, at.y, {0.5f, 0.5f, 0.25f, 1.0f});
        gl::Texture ti = upload(image), tr = upload(reference);
        ErrorMap map;
        const ErrorMapStats s = map.compare(ti.id(), tr.id(), size);
        CHECK(s.worstPixel == at);
        CHECK(s.maxAbsError == 0.25);
        CHECK(s.rmse == doctest::Approx(std::sqrt(0.0625 / (3.0 * size.x * size.y))).epsilon(1e-6));
    }
}

TEST_CASE("error map: the CPU false colour for reports is the GPU pass's, pixel for pixel") {
    test::Fixture f(makeBuiltinScene("cubes"));
    // Differences across the whole ramp (0 to twice the scale), some pixels identical.
    Image reference(37, 21), image(37, 21);
    for (int y = 0; y < 21; ++y)
        for (int x = 0; x < 37; ++x) {
            const glm::vec4 r(float(x) / 36.0f, float(y) / 20.0f, 0.5f, 1.0f);
            const float d = (x + y) % 5 == 0 ? 0.0f : 0.1f * float((x * 7 + y * 3) % 23) / 22.0f;
            reference.set(x, y, r);
            image.set(x, y, r + glm::vec4(0.0f, d, -0.5f * d, 0.0f));
        }
    const gl::Texture ti = upload(image), tr = upload(reference);
    ErrorMap map;
    map.compare(ti.id(), tr.id(), {37, 21}, 0.05f);
    gl::checkGl("error map");
    const Image gpu = readRgbaTexture(map.falseColor(), {37, 21});
    const Image cpu = errorMapImage(image, reference, 0.05f);
    float worst = 0.0f;
    for (int y = 0; y < 21; ++y)
        for (int x = 0; x < 37; ++x)
            for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(gpu.at(x, y)[c] - cpu.at(x, y)[c]));
    CHECK(worst <= 1e-5f);
    // The ramp's ends as stated: red at and above the scale, dark grey where nothing differs.
    // At (2, 0) green differs by 0.1 * 14/22 = 0.064, over the scale: the ramp's last stop.
    CHECK(cpu.at(2, 0) == glm::vec4(0.95f, 0.05f, 0.03f, 1.0f));
    CHECK(cpu.at(0, 0) == glm::vec4(glm::vec3(0.03f + 0.22f * glm::dot(glm::vec3(reference.at(0, 0)), glm::vec3(0.2126f, 0.7152f, 0.0722f))), 1.0f));
    CHECK_THROWS_AS(errorMapImage(image, Image(3, 3)), std::invalid_argument);
}

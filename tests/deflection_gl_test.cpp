// Image deflection on the GPU (core/render/deflection_warp) driven by tracking's deflection math.
//
// The warp's own conventions are pinned on synthetic textures (integer shifts are exact, the
// border count is known, a homography matches a CPU evaluation of the same inverse map, and
// tracking's y-down forward homography becomes the GL y-up inverse map). Then the check:
// a scene rendered at orientation A and warped with tracking's homography for A -> B reproduces
// the scene rendered at B (same camera position: a pure rotation, which a homography maps
// exactly at every depth); the shift matches to first order. Tolerance 2/255: the shading of a
// surface point does not depend on the camera orientation, so only resampling differs.
//
// Why the comparison is not exact, and how each test deals with it: image A is point-sampled at
// A's pixel centres, which land up to half a pixel (nearest) or a pixel (bilinear) away from
// B's pixel centres. On an edge that is a whole edge contrast, so
//  - smooth content (the camera inside two nested spheres, no edges) measures the geometry:
//    bilinear resampling error is second order; nearest is compared with B bilinearly sampled
//    where the exact map's texel lands (snappedReference), so the snapping cancels;
//  - builtin:default (many edges) requires B's flat pixels (3x3 neighbourhood within the
//    tolerance) to match and the homography to beat the shift overall.
#include "gl_test_support.hpp"

#include "render/deflection_warp.hpp"
#include "render/texture_readback.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh_builders.hpp"
#include "tracking/deflection.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace strata;

namespace {

constexpr float kTolerance = 2.0f / 255.0f;

// --- bridges between tracking (Eigen, double) and core (glm) --------------------------------

using tracking::toEigen;
using tracking::toGlm;

// tracking's pinhole for core's camera: fovY, square pixels, principal point at the centre.
tracking::Intrinsics intrinsicsFor(const Camera& camera, glm::ivec2 size) {
    return tracking::Intrinsics::fromFovY(size.x, size.y, camera.fovYDegrees);
}

DeflectionParams homographyParams(const tracking::Intrinsics& k, const glm::quat& rendered, const glm::quat& latest,
                                  DeflectFilter filter) {
    DeflectionParams p;
    p.mode = DeflectMode::Homography;
    p.homography = homographyFromYDownForward(
        toGlm(tracking::deflectionHomography(k, toEigen(rendered), toEigen(latest))), k.height);
    p.filter = filter;
    p.border = glm::vec4(0.0f);  // alpha 0 marks pixels that map outside the source
    return p;
}

DeflectionParams shiftParams(const tracking::Intrinsics& k, const glm::quat& rendered, const glm::quat& latest,
                             DeflectFilter filter) {
    DeflectionParams p;
    p.mode = DeflectMode::Shift;
    const Eigen::Vector2d s = tracking::deflectionShift(k, toEigen(rendered), toEigen(latest));
    p.shift = shiftFromYDown({s.x(), s.y()});
    p.filter = filter;
    p.border = glm::vec4(0.0f);
    return p;
}

glm::vec2 applyMap(const glm::mat3& m, glm::vec2 p) {
    glm::vec3 h = m * glm::vec3(p, 1.0f);
    return glm::vec2(h) / h.z;
}

// A camera-local rotation (yaw about +Y, pitch about +X, roll about -Z, degrees) applied to q.
glm::quat rotatedLocal(const glm::quat& q, float yawDeg, float pitchDeg, float rollDeg) {
    glm::quat r = glm::angleAxis(glm::radians(yawDeg), glm::vec3(0, 1, 0)) *
                  glm::angleAxis(glm::radians(pitchDeg), glm::vec3(1, 0, 0)) *
                  glm::angleAxis(glm::radians(rollDeg), glm::vec3(0, 0, -1));
    return glm::normalize(q * r);
}

float maxChannelDiff(const glm::vec4& a, const glm::vec4& b) {
    glm::vec3 d = glm::abs(glm::vec3(a) - glm::vec3(b));
    return std::max(d.r, std::max(d.g, d.b));
}

struct Match {
    std::size_t valid = 0, within = 0;        // pixels mapping inside the source; of those within tolerance
    std::size_t interior = 0, interiorWithin = 0;  // the same over B's flat pixels
    double meanAbs = 0.0;                     // mean over valid pixels of the mean RGB difference
    double fraction() const { return valid ? double(within) / double(valid) : 0.0; }
    double interiorFraction() const { return interior ? double(interiorWithin) / double(interior) : 0.0; }
};

// Compares a warped image (border alpha 0) with the truth over `region` (x0, y0, x1, y1).
Match compareWarped(const Image& warped, const Image& truth, glm::ivec4 region) {
    Match m;
    for (int y = region.y; y < region.w; ++y)
        for (int x = region.x; x < region.z; ++x) {
            glm::vec4 w = warped.at(x, y);
            if (w.a < 0.5f) continue;
            glm::vec4 t = truth.at(x, y);
            float d = maxChannelDiff(w, t);
            ++m.valid;
            if (d <= kTolerance) ++m.within;
            glm::vec3 dd = glm::abs(glm::vec3(w) - glm::vec3(t));
            m.meanAbs += (dd.r + dd.g + dd.b) / 3.0;
            bool flat = true;
            for (int dy = -1; dy <= 1 && flat; ++dy)
                for (int dx = -1; dx <= 1 && flat; ++dx) {
                    int nx = std::clamp(x + dx, 0, truth.width - 1), ny = std::clamp(y + dy, 0, truth.height - 1);
                    flat = maxChannelDiff(truth.at(nx, ny), t) <= kTolerance;
                }
            if (flat) {
                ++m.interior;
                if (d <= kTolerance) ++m.interiorWithin;
            }
        }
    if (m.valid) m.meanAbs /= double(m.valid);
    return m;
}

// Bilinear sample of an image at a GL pixel position (texel centres at integer + 0.5, edges
// repeated), the same formula as the shader's.
glm::vec4 sampleBilinear(const Image& image, glm::vec2 q) {
    const glm::vec2 t = q - 0.5f;
    const glm::ivec2 i0 = glm::ivec2(glm::floor(t));
    const glm::vec2 f = t - glm::vec2(i0);
    auto at = [&](int x, int y) {
        return image.at(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
    };
    return glm::mix(glm::mix(at(i0.x, i0.y), at(i0.x + 1, i0.y), f.x),
                    glm::mix(at(i0.x, i0.y + 1), at(i0.x + 1, i0.y + 1), f.x), f.y);
}

// The truth "with the same sampling" for a nearest-sampled warp of smooth content: output pixel
// p shows source texel t = floor(M p) of the exact inverse map M, whose centre the exact
// forward map sends to M^-1 (t + 0.5) in B, generally not p; B there (bilinear, accurate on
// smooth content) is what a correct nearest deflection shows. Against this reference the
// half-pixel snapping cancels and only a wrong map leaves error.
Image snappedReference(const Image& truth, const glm::mat3& exactInverseMap) {
    const glm::mat3 forward = glm::inverse(exactInverseMap);
    const glm::ivec2 size(truth.width, truth.height);
    Image ref(truth.width, truth.height);
    for (int y = 0; y < truth.height; ++y)
        for (int x = 0; x < truth.width; ++x) {
            const glm::ivec2 t = glm::clamp(glm::ivec2(glm::floor(applyMap(exactInverseMap, {x + 0.5f, y + 0.5f}))),
                                            glm::ivec2(0), size - 1);
            ref.set(x, y, sampleBilinear(truth, applyMap(forward, glm::vec2(t) + 0.5f)));
        }
    return ref;
}

gl::Texture uploadImage(const Image& image) {
    gl::Texture t = gl::createTexture2D(GL_RGBA32F, image.width, image.height);
    glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT, image.rgba.data());
    return t;
}

Image randomImage(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.set(x, y, {u(rng), u(rng), u(rng), 1.0f});
    return image;
}

// Smooth content: the camera at the centre of an opaque sphere inside a transparent one (both
// two-sided Lambert, finely tessellated), lit from the side so the colour varies across the view
// by ~1/255 per pixel but has no edges. Resampling then costs almost nothing (bilinear error is
// second order), so what the comparison measures is the geometry of the deflection.
Scene makeSmoothScene() {
    Scene s;
    s.name = "smooth spheres";
    s.materials.push_back(Material{});
    s.background = {0.0f, 0.0f, 0.0f};
    s.lightDirection = glm::normalize(glm::vec3(1.0f, 0.8f, 1.0f));
    auto addSphere = [&](float radius, glm::vec3 colour, float alpha) {
        Material m;
        m.baseColor = colour;
        m.alpha = alpha;
        m.alphaMode = alpha < 1.0f ? AlphaMode::Blend : AlphaMode::Opaque;
        Node node;
        node.meshes = {s.addMesh(makeSphere(radius, 192, 96))};
        node.materialOverride = s.addMaterial(m);
        s.addNode(node);
    };
    addSphere(20.0f, {0.9f, 0.85f, 0.8f}, 1.0f);
    addSphere(10.0f, {0.2f, 0.4f, 0.9f}, 0.4f);
    return s;
}

struct SceneFixture {
    std::unique_ptr<GpuScene> gpu;
    Camera camera;
    glm::ivec2 size{96, 72};
    explicit SceneFixture(Scene scene, bool centred) {
        test::glContext();
        gpu = std::make_unique<GpuScene>(std::move(scene));
        camera = defaultCamera(gpu->scene(), gpu->objects());
        if (centred) {
            camera = Camera{};
            camera.position = glm::vec3(0.0f);
            camera.orientation = glm::angleAxis(glm::radians(20.0f), glm::vec3(0, 1, 0));
            camera.nearPlane = 0.1f;
            camera.farPlane = 100.0f;
        }
    }
    Image render(const glm::quat& orientation) {
        Camera c = camera;
        c.orientation = orientation;
        return test::renderWith(*gpu, c, size, "abuffer").image;
    }
};

struct PairResult {
    Match homography, shift;
};

// Renders A and B = A rotated (camera-local yaw, pitch, roll in degrees) from the same
// position, warps A into B's view both ways from the renderer's own output texture and
// compares with B over the whole image.
// With `snapped`, nearest warps are compared with snappedReference (smooth content only).
PairResult warpAndCompare(SceneFixture& f, float yaw, float pitch, float roll, DeflectFilter filter,
                          bool snapped = false) {
    const glm::quat a = f.camera.orientation;
    const glm::quat b = rotatedLocal(a, yaw, pitch, roll);
    const tracking::Intrinsics k = intrinsicsFor(f.camera, f.size);
    FrameRenderer renderer;
    auto technique = createTechnique("abuffer");
    renderer.render(*f.gpu, f.camera, f.size, technique.get());
    const Image rendered = f.render(b);
    const DeflectionParams exact = homographyParams(k, a, b, filter);
    const Image truth = snapped && filter == DeflectFilter::Nearest ? snappedReference(rendered, exact.homography)
                                                                   : rendered;
    DeflectionWarp warp;
    PairResult r;
    const glm::ivec4 all(0, 0, f.size.x, f.size.y);
    warp.apply(renderer.targets().outputColor(), f.size, exact);
    r.homography = compareWarped(warp.readOutput(), truth, all);
    warp.apply(renderer.targets().outputColor(), f.size, shiftParams(k, a, b, filter));
    const Image shifted = warp.readOutput();
    r.shift = compareWarped(shifted, truth, all);
    gl::checkGl("warp");
    if (r.homography.fraction() < 0.999) {  // what a failing case rendered (STRATA_TEST_DUMP)
        char name[96];
        std::snprintf(name, sizeof name, "deflection-%s-y%.1f-p%.1f-r%.1f-%s", f.gpu->scene().name.c_str(), yaw, pitch,
                      roll, std::string(deflectFilterName(filter)).c_str());
        test::dumpImage(std::string(name) + "-a", readRgbaTexture(renderer.targets().outputColor(), f.size));
        test::dumpImage(std::string(name) + "-b", rendered);
        warp.apply(renderer.targets().outputColor(), f.size, exact);
        test::dumpImage(std::string(name) + "-warped", warp.readOutput());
        test::dumpImage(std::string(name) + "-shifted", shifted);
    }
    std::printf("deflection %s yaw %.1f pitch %.1f roll %.1f %s: homography %.4f of %zu within 2/255 (flat %.4f), "
                "mean |d| %.6f; shift %.4f of %zu (flat %.4f), mean |d| %.6f\n",
                f.gpu->scene().name.c_str(), yaw, pitch, roll, std::string(deflectFilterName(filter)).c_str(),
                r.homography.fraction(), r.homography.valid, r.homography.interiorFraction(), r.homography.meanAbs,
                r.shift.fraction(), r.shift.valid, r.shift.interiorFraction(), r.shift.meanAbs);
    return r;
}

}  // namespace

TEST_CASE("deflection warp: integer shifts move texels exactly and count the uncovered border") {
    test::glContext();
    const Image src = randomImage(40, 30, 7);
    gl::Texture tex = uploadImage(src);
    DeflectionWarp warp;
    for (DeflectFilter filter : {DeflectFilter::Nearest, DeflectFilter::Bilinear}) {
        CAPTURE(deflectFilterName(filter));
        DeflectionParams p;
        p.mode = DeflectMode::Shift;
        p.shift = {3.0f, -2.0f};  // content right by 3 and down by 2 (GL y up)
        p.filter = filter;
        p.border = {0.25f, 0.5f, 0.75f, 0.0f};
        p.countOutside = true;
        warp.apply(tex.id(), {40, 30}, p);
        const Image out = warp.readOutput();
        gl::checkGl("shift");
        std::size_t wrong = 0, border = 0;
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) {
                const int sx = x - 3, sy = y + 2;
                const bool inside = sx >= 0 && sy < 30;
                const glm::vec4 expected = inside ? src.at(sx, sy) : p.border;
                border += inside ? 0 : 1;
                if (out.at(x, y) != expected) ++wrong;
            }
        CHECK(wrong == 0);
        CHECK(border == 3u * 30u + 2u * 40u - 3u * 2u);
        CHECK(warp.outsidePixels() == border);
    }
}

TEST_CASE("deflection warp: a homography samples the source where the CPU evaluation of its inverse map says") {
    test::glContext();
    const glm::ivec2 size(48, 36);
    const Image src = randomImage(size.x, size.y, 11);
    gl::Texture tex = uploadImage(src);
    // A rotation about the image centre with some perspective: generic, not pixel-aligned.
    glm::mat3 m(1.0f);
    const float c = std::cos(0.05f), s = std::sin(0.05f);
    glm::mat3 toCentre(1.0f), back(1.0f), rot(1.0f), persp(1.0f);
    toCentre[2] = glm::vec3(-24.0f, -18.0f, 1.0f);
    back[2] = glm::vec3(24.3f, 17.6f, 1.0f);
    rot[0] = glm::vec3(c, s, 0.0f);
    rot[1] = glm::vec3(-s, c, 0.0f);
    persp[0][2] = 0.002f;
    m = back * persp * rot * toCentre;
    DeflectionParams p;
    p.mode = DeflectMode::Homography;
    p.homography = m;
    p.filter = DeflectFilter::Nearest;
    p.border = glm::vec4(0.0f);
    p.countOutside = true;
    DeflectionWarp warp;
    warp.apply(tex.id(), size, p);
    const Image out = warp.readOutput();
    gl::checkGl("homography");
    std::size_t checked = 0, wrong = 0, outside = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const glm::vec2 q = applyMap(m, {x + 0.5f, y + 0.5f});
            const bool in = q.x >= 0 && q.y >= 0 && q.x <= size.x && q.y <= size.y;
            // Points within 1e-3 of a texel boundary may round either way in the GPU's float math.
            const glm::vec2 fr = q - glm::floor(q);
            if (glm::any(glm::lessThan(fr, glm::vec2(1e-3f))) || glm::any(glm::greaterThan(fr, glm::vec2(1 - 1e-3f))))
                continue;
            ++checked;
            if (!in) {
                ++outside;
                if (out.at(x, y) != p.border) ++wrong;
                continue;
            }
            const glm::ivec2 t = glm::clamp(glm::ivec2(glm::floor(q)), glm::ivec2(0), size - 1);
            if (out.at(x, y) != src.at(t.x, t.y)) ++wrong;
        }
    CHECK(checked > std::size_t(size.x * size.y * 9 / 10));
    CHECK(outside > 0);
    CHECK(wrong == 0);
    CHECK(warp.outsidePixels() >= outside);
    CHECK(warp.outsidePixels() <= outside + (size.x * size.y - checked));
}

TEST_CASE("deflection conventions: tracking's homography and shift agree at the image centre in GL pixels") {
    // Yaw and pitch only: to first order both maps move the centre by the same amount, so the
    // y flip and the inversion must have been done consistently for both.
    Camera camera;
    const glm::ivec2 size(96, 72);
    const tracking::Intrinsics k = intrinsicsFor(camera, size);
    const glm::quat a = glm::angleAxis(0.3f, glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f)));
    const glm::quat b = rotatedLocal(a, 0.5f, -0.3f, 0.0f);
    const auto h = homographyParams(k, a, b, DeflectFilter::Nearest);
    const auto sh = shiftParams(k, a, b, DeflectFilter::Nearest);
    const glm::vec2 centre(48.0f, 36.0f);
    const glm::vec2 viaH = applyMap(deflectionInverseMap(h), centre);
    const glm::vec2 viaS = applyMap(deflectionInverseMap(sh), centre);
    CHECK(glm::length(viaH - viaS) < 0.01f);
    // Turning left (positive yaw) shows content that was left of the centre: the source of the
    // output centre lies left of it (smaller x); looking down (negative pitch) shows what was below.
    CHECK(viaH.x < centre.x - 0.5f);
    CHECK(viaH.y < centre.y - 0.3f);
    // And the homography reprojects world directions the way the camera does: a direction
    // projecting to output pixel p under B projects to source pixel H^-1 p under A.
    const Eigen::Vector3d dir = tracking::unprojectPixel(k, toEigen(b), Eigen::Vector2d(30.5, 20.5));
    Eigen::Vector2d inA;
    REQUIRE(tracking::projectDirection(k, toEigen(a), dir, inA));
    const glm::vec2 glOut(30.5f, float(size.y) - 20.5f);
    const glm::vec2 glSrc = applyMap(h.homography, glOut);
    CHECK(glSrc.x == doctest::Approx(inA.x()).epsilon(1e-4));
    CHECK(glSrc.y == doctest::Approx(size.y - inA.y()).epsilon(1e-4));
}

TEST_CASE("deflection of a smooth rendered frame: homography reproduces the rotated view, shift to first order") {
    SceneFixture f(makeSmoothScene(), true);
    for (DeflectFilter filter : {DeflectFilter::Bilinear, DeflectFilter::Nearest}) {
        CAPTURE(deflectFilterName(filter));
        double previousShift = 0.0, firstShift = 0.0;
        for (float scale : {0.5f, 1.0f, 2.0f}) {
            CAPTURE(scale);
            const PairResult r = warpAndCompare(f, 2.0f * scale, 1.0f * scale, 0.0f, filter, true);
            REQUIRE(r.homography.valid > std::size_t(f.size.x * f.size.y * 8 / 10));
            // Bilinear leaves only the curvature term of the interpolation (the reference for
            // nearest is itself a bilinear sample of B), far inside 2/255 everywhere.
            CHECK(r.homography.fraction() >= 0.999);
            CHECK(r.homography.meanAbs < 2e-4);
            // The shift's residual misplacement is f theta tan^2(off-axis angle) plus cross
            // terms: linear in the angle away from the centre, so its error roughly doubles
            // with the angle (bilinear), while the homography's stays at the resampling floor.
            // Nearest quantises the residual to whole texels, so there it only has to grow
            // from the smallest to the largest angle.
            CHECK(r.shift.meanAbs > 2.0 * r.homography.meanAbs);
            if (filter == DeflectFilter::Bilinear) CHECK(r.shift.meanAbs > 1.5 * previousShift);
            if (filter == DeflectFilter::Nearest && scale == 2.0f) CHECK(r.shift.meanAbs > 1.5 * firstShift);
            if (scale == 0.5f) firstShift = r.shift.meanAbs;
            previousShift = r.shift.meanAbs;
        }
    }
}

TEST_CASE("deflection of a smooth rendered frame with roll: the homography corrects it, the shift cannot") {
    SceneFixture f(makeSmoothScene(), true);
    for (float roll : {1.0f, 2.0f}) {
        const PairResult r = warpAndCompare(f, 2.0f, 1.0f, roll, DeflectFilter::Bilinear);
        CHECK(r.homography.fraction() >= 0.999);
        CHECK(r.homography.meanAbs < 2e-4);
        CHECK(r.shift.meanAbs > 5.0 * r.homography.meanAbs);
    }
}

TEST_CASE("deflection of a rendered frame with edges (builtin:default): flat regions reproduce exactly") {
    // Here resampling at edges dominates: a pixel on an edge in B sees A's content up to half a
    // pixel (nearest) or a pixel (bilinear) away, which is a full edge contrast. Over B's flat
    // pixels the homography must match; over all pixels it must beat the shift.
    SceneFixture f(makeBuiltinScene("default"), false);
    for (DeflectFilter filter : {DeflectFilter::Nearest, DeflectFilter::Bilinear}) {
        CAPTURE(deflectFilterName(filter));
        for (glm::vec3 ypr : {glm::vec3(2, 1, 0), glm::vec3(4, 2, 0), glm::vec3(0, 0, 1), glm::vec3(2, 1, 1)}) {
            CAPTURE(ypr);
            const PairResult r = warpAndCompare(f, ypr.x, ypr.y, ypr.z, filter);
            REQUIRE(r.homography.valid > std::size_t(f.size.x * f.size.y / 2));
            CHECK(r.homography.interiorFraction() >= 0.995);
            // Over all pixels: edges are what remains. builtin:default's dense relief of blocks and
            // the globe's wireframe put ~15 % (nearest) to ~30 % (bilinear) of its 48x36 pixels on an
            // edge (measured 0.846-0.886 and 0.70-0.75); the bounds sit below that.
            CHECK(r.homography.fraction() >= (filter == DeflectFilter::Nearest ? 0.80 : 0.65));
            CHECK(r.shift.meanAbs > r.homography.meanAbs);
        }
    }
}

TEST_CASE("deflection of a rendered frame, pure yaw: the shift is near-exact in the centre region") {
    SceneFixture f(makeBuiltinScene("default"), false);
    const glm::quat a = f.camera.orientation;
    const glm::quat b = rotatedLocal(a, 2.0f, 0.0f, 0.0f);
    const tracking::Intrinsics k = intrinsicsFor(f.camera, f.size);
    const auto h = homographyParams(k, a, b, DeflectFilter::Nearest);
    const auto sh = shiftParams(k, a, b, DeflectFilter::Nearest);
    // The middle half of the image in each direction.
    const glm::ivec4 centre(f.size.x / 4, f.size.y / 4, 3 * f.size.x / 4, 3 * f.size.y / 4);
    // Geometry first: over the centre region the two inverse maps differ by well under the
    // half pixel at which nearest sampling could pick a different texel (x theta tan^2 and
    // x y theta / f terms: ~0.25 px at the region's corners for 2 degrees).
    float maxGap = 0.0f;
    for (int y = centre.y; y < centre.w; ++y)
        for (int x = centre.x; x < centre.z; ++x) {
            const glm::vec2 p(x + 0.5f, y + 0.5f);
            maxGap = std::max(maxGap, glm::length(applyMap(deflectionInverseMap(h), p) -
                                                  applyMap(deflectionInverseMap(sh), p)));
        }
    std::printf("deflection pure yaw 2.0: shift vs homography source positions over the centre region differ "
                "by at most %.3f px\n", maxGap);
    CHECK(maxGap < 0.35f);
    // Pixels: the shift matches B over the centre region nearly as well as the homography.
    Camera ca = f.camera;
    FrameRenderer renderer;
    auto technique = createTechnique("abuffer");
    renderer.render(*f.gpu, ca, f.size, technique.get());
    const Image truth = f.render(b);
    DeflectionWarp warp;
    warp.apply(renderer.targets().outputColor(), f.size, h);
    const Match mh = compareWarped(warp.readOutput(), truth, centre);
    warp.apply(renderer.targets().outputColor(), f.size, sh);
    const Match ms = compareWarped(warp.readOutput(), truth, centre);
    std::printf("deflection pure yaw 2.0 centre region: homography %.4f within (mean |d| %.5f), "
                "shift %.4f within (mean |d| %.5f)\n", mh.fraction(), mh.meanAbs, ms.fraction(), ms.meanAbs);
    CHECK(mh.valid == std::size_t((centre.z - centre.x) * (centre.w - centre.y)));
    CHECK(ms.valid == mh.valid);
    CHECK(ms.interiorFraction() >= 0.99);
    CHECK(ms.fraction() >= mh.fraction() - 0.03);
}

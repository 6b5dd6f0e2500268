// Layered impostors on the GPU (lod/layered_impostor.hpp, lod/impostor_set.hpp): the baked atlas
// against the analytic sphere, peels, rectangles, memory, the degenerate inputs, the per-frame
// ranges and hole filling; and (below) impostor renders against geometry renders.
#include "test_paths.hpp"
#include "gl_test_support.hpp"

#include "lod/impostor_set.hpp"
#include "lod/layered_impostor.hpp"
#include "lod/view_directions.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/scene_source.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

using namespace strata;
using namespace strata::lod;

namespace {

Scene singleObjectScene(Mesh mesh, Material material = {}, const glm::mat4& world = glm::mat4(1.0f)) {
    Scene s;
    s.name = "impostor-test";
    s.materials = {Material{}};
    const int m = s.addMaterial(material);
    mesh.material = m;
    Node node;
    node.local = world;
    node.meshes = {s.addMesh(std::move(mesh))};
    s.addNode(node);
    return s;
}

std::vector<std::uint8_t> readAtlas(const LayeredImpostor& imp) {
    const int res = imp.settings().resolution, layers = imp.settings().views * imp.settings().peels;
    std::vector<std::uint8_t> texels(std::size_t(res) * res * 4 * layers);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(imp.atlas(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(texels.size()), texels.data());
    gl::checkGl("read atlas");
    return texels;
}

// Distances from the ray origin o (unit direction d) to a sphere (c, R): near and far, or none.
bool raySphere(const glm::vec3& o, const glm::vec3& d, const glm::vec3& c, float R, float& tNear, float& tFar,
               float& missDistance) {
    const glm::vec3 oc = c - o;
    const float along = glm::dot(oc, d);
    missDistance = std::sqrt(std::max(0.0f, glm::dot(oc, oc) - along * along));
    if (missDistance > R) return false;
    const float half = std::sqrt(R * R - missDistance * missDistance);
    tNear = along - half;
    tFar = along + half;
    return true;
}

struct SphereCheck {
    int interior = 0, wrongCoverage = 0, outside = 0, falseHits = 0;
    float maxTError = 0.0f, minNormalDot = 1.0f;
};

// Every texel of `peel` against the analytic sphere (centre c, radius R) the tessellated mesh
// approximates: texels whose ray passes within 0.9 R of the centre must hold the far (peel 0)
// or near (peel 1) intersection and its normal; rays that miss by 1.1 R must be empty.
SphereCheck checkSphere(const LayeredImpostor& imp, const std::vector<std::uint8_t>& texels, const glm::vec3& c,
                        float R, int peel) {
    SphereCheck out;
    const int res = imp.settings().resolution, peels = imp.settings().peels;
    for (int view = 0; view < imp.settings().views; ++view) {
        const ImpostorFrame& f = imp.frame(view);
        const std::uint8_t* layer = texels.data() + std::size_t(view * peels + peel) * res * res * 4;
        for (int y = 0; y < res; ++y)
            for (int x = 0; x < res; ++x) {
                const std::uint8_t* t = layer + (std::size_t(y) * res + x) * 4;
                const glm::vec3 through = f.fromUvt({(x + 0.5f) / res, (y + 0.5f) / res, 0.5f});
                const glm::vec3 d = glm::normalize(through - f.apex);
                float tn = 0, tf = 0, miss = 0;
                const bool hit = raySphere(f.apex, d, c, R, tn, tf, miss);
                if (!hit || miss > 1.1f * R) {
                    ++out.outside;
                    if (t[3] != 0) ++out.falseHits;
                    continue;
                }
                if (miss > 0.9f * R) continue;  // the rim: tessellation decides
                ++out.interior;
                if (t[3] == 0) { ++out.wrongCoverage; continue; }
                const glm::vec3 p = f.apex + d * (peel == 0 ? tf : tn);
                const float expected = f.toUvt(p).z;
                const float stored = (float(t[3]) - 0.5f) / 255.0f;
                out.maxTError = std::max(out.maxTError, std::abs(stored - expected));
                const glm::vec3 n = glm::vec3(t[0], t[1], t[2]) / 255.0f * 2.0f - 1.0f;
                out.minNormalDot = std::min(out.minNormalDot, glm::dot(glm::normalize(n), glm::normalize(p - c)));
            }
    }
    return out;
}

}  // namespace

TEST_CASE("lod impostor gl: a sphere's atlas holds the far surface's depth code and normal per view") {
    // R = 1 sphere (64 x 32 facets: at most 0.5% of R inside the true sphere) off the origin;
    // the bounding sphere is the box's, radius sqrt(3). Expected per texel: the ray from the
    // apex meets the sphere; t of the far hit within the code's half-bin (0.5/255) plus the
    // facets' inset over the slab (0.005 / 3.46): 0.004; normals within 0.99.
    const glm::vec3 c(0.5f, -1.0f, 2.0f);
    for (float scale : {1.0f, 1.0e5f}) {  // a huge object: everything is relative to the sphere
        Mesh m = makeSphere(scale, 64, 32);
        for (auto& p : m.positions) p += c * scale;
        test::Fixture fx(singleObjectScene(m));
        ImpostorSettings settings;
        settings.views = 20;
        settings.resolution = 64;
        settings.slices = 16;
        const LayeredImpostor imp(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), settings);
        gl::checkGl("bake");
        REQUIRE(imp.valid());
        CHECK(imp.radius() == doctest::Approx(std::sqrt(3.0f) * scale).epsilon(1e-3));
        const SphereCheck s = checkSphere(imp, readAtlas(imp), c * scale, scale, 0);
        MESSAGE("scale ", scale, ": interior texels ", s.interior, ", uncovered ", s.wrongCoverage, ", max t error ",
                s.maxTError, ", min normal dot ", s.minNormalDot, ", outside texels ", s.outside, " with ",
                s.falseHits, " hits");
        CHECK(s.interior > 20 * 64 * 64 / 8);
        CHECK(s.wrongCoverage == 0);
        CHECK(s.falseHits == 0);
        CHECK(s.maxTError <= 0.004f);
        CHECK(s.minNormalDot >= 0.99f);
    }
}

TEST_CASE("lod impostor gl: transparent peels keep the far then the near surface") {
    const glm::vec3 c(0.0f);
    Material glass;
    glass.alphaMode = AlphaMode::Blend;
    glass.alpha = 0.5f;
    test::Fixture fx(singleObjectScene(makeSphere(1.0f, 64, 32), glass));
    ImpostorSettings settings;
    settings.views = 12;
    settings.resolution = 48;
    settings.slices = 8;
    settings.overlap = 0.5f;
    settings.peels = 3;
    const LayeredImpostor imp(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), settings);
    REQUIRE(imp.valid());
    CHECK(imp.settings().overlap == 0.0f);  // forced: no surface twice
    const auto texels = readAtlas(imp);
    const SphereCheck far = checkSphere(imp, texels, c, 1.0f, 0), near = checkSphere(imp, texels, c, 1.0f, 1);
    MESSAGE("peel 0 max t error ", far.maxTError, ", peel 1 max t error ", near.maxTError);
    CHECK(far.wrongCoverage == 0);
    CHECK(near.wrongCoverage == 0);
    CHECK(far.maxTError <= 0.004f);
    CHECK(near.maxTError <= 0.004f);
    CHECK(near.minNormalDot >= 0.99f);
    // A convex object has two surfaces per ray: the third peel is empty.
    const int res = 48;
    for (int view = 0; view < 12; ++view)
        for (int i = 0; i < res * res; ++i) CHECK(texels[(std::size_t(view * 3 + 2) * res * res + i) * 4 + 3] == 0);
}

namespace {

// Checks every rectangle and quad of `level` (with L slices) against the texels, by the
// contract's rule in float as the shader does it (strict) and the same rule with 1e-4 slice widths
// of margin at its boundaries (loose): a code whose t * L falls on a slice boundary may round
// either way on a GPU, so the rectangles include it in both slices. Expected: strict inside r, r
// equal to loose. Returns the level's non-empty slices.
int checkLevelRectangles(const LayeredImpostor& imp, const std::vector<std::uint8_t>& texels, int res, int views,
                         int L, int level, float overlap) {
    int nonEmpty = 0;
    for (int view = 0; view < views; ++view)
        for (int s = 0; s < L; ++s) {
            struct Rect { int x0 = 1 << 20, y0 = 1 << 20, x1 = -1, y1 = -1; };
            Rect strict, loose;
            auto grow = [](Rect& r, int x, int y) {
                r.x0 = std::min(r.x0, x), r.y0 = std::min(r.y0, y), r.x1 = std::max(r.x1, x), r.y1 = std::max(r.y1, y);
            };
            for (int y = 0; y < res; ++y)
                for (int x = 0; x < res; ++x) {
                    const int code = texels[(std::size_t(view) * res * res + std::size_t(y) * res + x) * 4 + 3];
                    if (code == 0) continue;
                    const float t = (float(code) - 0.5f) / 255.0f;
                    const bool accept = overlap == 0.0f
                                            ? std::min(int(t * float(L)), L - 1) == s
                                            : std::abs(t - (float(s) + 0.5f) / float(L)) <= (0.5f + overlap) / float(L);
                    const double tL = (double(code) - 0.5) / 255.0 * L, m = 1e-4;
                    const bool nearBoundary =
                        overlap == 0.0f ? (std::floor(tL - m) == s || std::floor(tL + m) == s)
                                        : (s >= std::ceil(tL - 1.0 - overlap - m) && s <= std::floor(tL + overlap + m));
                    if (accept) grow(strict, x, y);
                    if (accept || nearBoundary) grow(loose, x, y);
                }
            const SliceRect r = imp.rectangle(view, 0, s, level);
            const auto [first, count] = imp.sliceRange(view, 0, s, level);
            if (loose.x1 < 0) {
                CHECK(r.empty());
                CHECK(count == 0);
                continue;
            }
            ++nonEmpty;
            CHECK(count == 6);
            CHECK(int(r.x0) == loose.x0);
            CHECK(int(r.y0) == loose.y0);
            CHECK(int(r.x1) == loose.x1);
            CHECK(int(r.y1) == loose.y1);
            if (strict.x1 >= 0) {
                CHECK(int(r.x0) <= strict.x0);
                CHECK(int(r.y0) <= strict.y0);
                CHECK(int(r.x1) >= strict.x1);
                CHECK(int(r.y1) >= strict.y1);
            }
        }
    return nonEmpty;
}

}  // namespace

TEST_CASE("lod impostor gl: rectangles bound exactly the texels each slice accepts; quads and memory") {
    test::Fixture fx(singleObjectScene(makeBox(glm::vec3(-1.0f, -0.5f, -0.25f), glm::vec3(1.0f, 0.5f, 0.25f))));
    for (float overlap : {0.0f, 0.5f, 2.0f}) {
        ImpostorSettings settings;
        settings.views = 12;
        settings.resolution = 40;
        settings.slices = 10;
        settings.overlap = overlap;
        const LayeredImpostor imp(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), settings);
        REQUIRE(imp.valid());
        // 10 slices halve to 5, under kLeastLevelSlices: one level.
        CHECK(imp.levels() == 1);
        const auto texels = readAtlas(imp);
        const int nonEmpty = checkLevelRectangles(imp, texels, 40, 12, 10, 0, overlap);
        CHECK(imp.quadCount() == nonEmpty);
        // Memory: Table 2's images, 4 bytes per rectangle, and the quads' vertices apart.
        const ImpostorMemory b = imp.bytes();
        CHECK(b.images == 4ull * 40 * 40 * 12);
        CHECK(b.rectangles == 4ull * 12 * 10);
        CHECK(b.vertexBuffer == std::uint64_t(imp.quadCount()) * 6 * 7 * sizeof(float));
        MESSAGE("overlap ", overlap, ": ", nonEmpty, " of ", 12 * 10, " slices drawn");
        if (overlap > 0.0f) {
            // More reach, no fewer slices.
            CHECK(nonEmpty >= 12);
        }
    }
}

TEST_CASE("lod impostor gl: levels of merged slices: 32, 16 and 8 slices from one bake, each exact") {
    // A level's slice accepts what 2^l neighbouring slices accept, with the overlap in its own
    // widths: its rectangles follow the same rule at L / 2^l, from the same texels. Fewer, larger
    // quads: at most the finer level's count, and the vertex buffer holds every level's.
    test::Fixture fx(singleObjectScene(makeSphere(1.0f, 24, 12)));
    ImpostorSettings settings;
    settings.views = 12;
    settings.resolution = 40;
    settings.slices = 32;
    // Built only when asked: without, the baked slices alone.
    CHECK(LayeredImpostor(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), settings).levels() == 1);
    settings.mergedLevels = true;
    const LayeredImpostor imp(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), settings);
    REQUIRE(imp.valid());
    REQUIRE(imp.levels() == 3);
    const auto texels = readAtlas(imp);
    int quads = 0;
    for (int level = 0; level < imp.levels(); ++level) {
        CAPTURE(level);
        const int L = 32 >> level;
        CHECK(imp.levelSlices(level) == L);
        const int nonEmpty = checkLevelRectangles(imp, texels, 40, 12, L, level, settings.overlap);
        CHECK(imp.quadCount(level) == nonEmpty);
        if (level > 0) CHECK(imp.quadCount(level) <= imp.quadCount(level - 1));
        quads += imp.quadCount(level);
        // A level's draw without hole filling: its slice count and the nearest view's
        // non-empty slices of this level, six vertices each.
        const glm::vec3 eye(0, 0, 5);
        const StandInDraw d = imp.drawFor(eye, false, level);
        CHECK(d.slices == L);
        GLsizei drawn = 0, expected = 0;
        for (GLsizei c : d.count) drawn += c;
        for (int s = 0; s < L; ++s) expected += imp.sliceRange(imp.nearestView(eye), 0, s, level).second;
        CHECK(drawn == expected);
        CHECK(expected > 0);
    }
    MESSAGE("quads by level: ", imp.quadCount(0), ", ", imp.quadCount(1), ", ", imp.quadCount(2));
    CHECK(imp.quadCount(2) < imp.quadCount(0) / 2);
    CHECK(imp.bytes().vertexBuffer == std::uint64_t(quads) * 6 * 7 * sizeof(float));
    // The rectangles' bytes stay the baked level's (the paper's formula): the coarser ones are
    // rebuilt from the images.
    CHECK(imp.bytes().rectangles == 4ull * 12 * 32);
}

TEST_CASE("lod impostor gl: no triangles, zero radius or bad settings give no impostor and a reason") {
    test::glContext();
    Mesh empty;
    empty.name = "empty";
    Mesh point = makeQuad(1.0f, 1.0f);
    for (auto& p : point.positions) p = glm::vec3(2.0f, 3.0f, 4.0f);  // all four corners in one point
    Mesh quad = makeQuad(1.0f, 1.0f);
    {
        test::Fixture fx(singleObjectScene(empty));
        const LayeredImpostor imp(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), {});
        CHECK_FALSE(imp.valid());
        CHECK(imp.reason() == "the mesh has no triangles");
        CHECK(imp.bytes().total() == 0);
        CHECK(imp.drawFor(glm::vec3(0, 0, 5)).first.empty());
    }
    {
        test::Fixture fx(singleObjectScene(point));
        const LayeredImpostor imp(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), {});
        CHECK_FALSE(imp.valid());
        CHECK(imp.reason() == "the mesh's bounding sphere has zero radius");
    }
    {
        test::Fixture fx(singleObjectScene(quad));
        ImpostorSettings bad;
        bad.views = 16;
        CHECK(LayeredImpostor(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), bad).reason() ==
              "impostor views must be 12, 20 or 32, not 16");
        bad = {};
        bad.slices = 0;
        CHECK_FALSE(LayeredImpostor(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), bad).valid());
        bad = {};
        bad.resolution = 300;
        CHECK_FALSE(LayeredImpostor(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), bad).valid());
    }
    gl::checkGl("degenerate impostors");
}

TEST_CASE("lod impostor gl: ranges per frame: the nearest view in full, holes from the two others") {
    // A torus-like concave object would have more holes; a box already shows its sides from
    // the halfway directions that the nearest view's image lacks.
    test::Fixture fx(singleObjectScene(makeBox(glm::vec3(-1.0f, -0.3f, -0.6f), glm::vec3(1.0f, 0.3f, 0.6f))));
    ImpostorSettings settings;
    settings.views = 12;
    settings.resolution = 64;
    settings.slices = 16;
    const LayeredImpostor imp(fx.gpu->meshOf(0), fx.gpu->scene().meshes[0].bounds(), settings);
    REQUIRE(imp.valid());
    CHECK(imp.adjacency().size() == 60);
    int withHoles = 0;
    for (auto [v, w] : imp.adjacency()) withHoles += imp.holeSlices(v, w).empty() ? 0 : 1;
    MESSAGE(withHoles, " of 60 adjacent pairs have hole-filling slices");
    CHECK(withHoles > 0);
    std::size_t mergedRuns = 0;  // hole slices drawn in the range of the slice before them
    for (int view = 0; view < 12; ++view) {
        const glm::vec3 eye = imp.centre() + imp.directions()[std::size_t(view)] * 10.0f;
        CHECK(imp.nearestView(eye) == view);
        CHECK(imp.nearestViewAngle(eye) < 1e-3f);
        const StandInDraw plain = imp.drawFor(eye, false);
        // One contiguous range: every non-empty slice of this view's stack, the slice nearest
        // the viewer (farthest from the apex) first, so its range starts at the last slice's.
        REQUIRE(plain.first.size() == 1);
        CHECK(imp.frontToBack());
        int expected = 0, firstVertex = -1, previousFirst = -1;
        for (int s = 15; s >= 0; --s) {
            const auto [first, count] = imp.sliceRange(view, 0, s);
            if (count == 0) continue;
            if (firstVertex < 0) firstVertex = first;
            CHECK(first > previousFirst);  // slice s after slice s + 1
            previousFirst = first;
            expected += count;
        }
        CHECK(plain.count[0] == expected);
        CHECK(plain.first[0] == firstVertex);
        CHECK(plain.slices == 16);
        CHECK(plain.overlap == 0.5f);
        CHECK(plain.atlas == imp.atlas());
        CHECK(plain.vertexArray == imp.vertexArray());
        const StandInDraw filled = imp.drawFor(eye, true);
        GLsizei total = 0, plainTotal = plain.count[0];
        for (auto c : filled.count) total += c;
        const auto n = nearestViews(imp.directions(), eye - imp.centre(), 3);
        std::size_t holes = imp.holeSlices(n[0], n[1]).size() + imp.holeSlices(n[0], n[2]).size();
        CHECK(total == plainTotal + GLsizei(holes) * 6);
        // A neighbour's hole slices s and s - 1 lie next to each other in its buffer (s first),
        // so each run of neighbouring slices is one range: at most the view's own range and one
        // per run of consecutive slice numbers (fewer where a run ends where another view's
        // range begins).
        std::size_t runs = 0;
        for (int k : {1, 2}) {
            const std::vector<int>& h = imp.holeSlices(n[0], n[std::size_t(k)]);
            for (std::size_t i = 0; i < h.size(); ++i) runs += (i == 0 || h[i] != h[i - 1] + 1) ? 1 : 0;
        }
        CHECK(filled.first.size() <= 1 + runs);
        mergedRuns += 1 + holes - filled.first.size();
    }
    MESSAGE(mergedRuns, " hole slices drawn in the range before them (12 views)");
    CHECK(mergedRuns > 0);
}

TEST_CASE("lod impostor gl: the set bakes the shipped bunny (res 128, 20 views, 64 slices) with a progress line") {
    const std::filesystem::path file = test::sharedScenesDir() / "stanford-bunny.glb";
    if (!std::filesystem::exists(file)) {
        MESSAGE("skipped: ", file.string(), " is absent");
        return;
    }
    test::Fixture fx(openScene(file.string()));
    ImpostorSettings settings;  // the defaults are the paper's: 128 px, 20 views, 64 slices
    REQUIRE(settings.resolution == 128);
    REQUIRE(settings.views == 20);
    REQUIRE(settings.slices == 64);
    std::ostringstream progress;
    const ImpostorSet set(*fx.gpu, settings, 2, &progress);
    gl::checkGl("bunny bake");
    MESSAGE(progress.str(), "triangles ", fx.gpu->triangleCount(), ", bake ", set.bakeMs(), " ms");
    CHECK(progress.str().find("baking impostors: 1/1") != std::string::npos);
    REQUIRE(set.bakedImpostors() == 1);
    const ImpostorMemory b = set.bytes();
    CHECK(b.images == 4ull * 128 * 128 * 20);  // 1.311 MB, Table 2
    CHECK(b.rectangles == 4ull * 20 * 64);
    CHECK(set.impostorOf(0) != nullptr);
    CHECK(set.reasonOf(0).empty());
}

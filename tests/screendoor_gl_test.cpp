// The screen-door family and its baselines (Sen, Chemudugunta, Gopi: silhouette-opaque
// transparency): crow against its formula on a sphere; the screen-door techniques' mean opacity
// on a flat quad against alpha within a tolerance derived from the sample count, independence
// of draw order, the alpha 0 and 1 extremes and bit-for-bit reproducibility from the seed.
#include "gl_test_support.hpp"

#include "scene/mesh_builders.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace strata;

namespace {

// |N_z| where pixel (x, y) of a `size` image (camera at the origin looking down -Z, vertical field
// of view `fovYDegrees`) first meets the unit sphere at `centre`, against the direction to the
// eye; negative where the pixel's ray misses the sphere.
double sphereFacing(int x, int y, glm::ivec2 size, double fovYDegrees, glm::vec3 centre) {
    const double t = std::tan(glm::radians(fovYDegrees) / 2.0);
    glm::dvec3 dir = glm::normalize(glm::dvec3(((x + 0.5) / size.x * 2.0 - 1.0) * t,
                                               ((y + 0.5) / size.y * 2.0 - 1.0) * t, -1.0));
    glm::dvec3 c(centre);
    double b = glm::dot(dir, c), disc = b * b - (glm::dot(c, c) - 1.0);
    if (disc < 0.0) return -1.0;
    return std::abs(glm::dot(glm::normalize(dir * (b - std::sqrt(disc)) - c), -dir));
}

// Unlit: the colour is the base colour, so coverage reads off the image as is.
Material transparentMaterial(glm::vec3 color, float alpha) {
    Material m;
    m.unlit = true;
    m.baseColor = color;
    m.alpha = alpha;
    m.alphaMode = AlphaMode::Blend;
    return m;
}

// A scene seen from the origin down -Z (fov 50 degrees) over a white background.
Scene emptyTestScene() {
    Scene s;
    s.materials.push_back(Material{});
    s.camera = CameraPose{};
    s.background = glm::vec3(1.0f);
    return s;
}

void place(Scene& s, Mesh mesh, const Material& material, const glm::mat4& world) {
    Node n;
    n.meshes = {s.addMesh(std::move(mesh))};
    n.materialOverride = s.addMaterial(material);
    n.local = world;
    s.addNode(std::move(n));
}

glm::mat4 at(glm::vec3 p) { return glm::translate(glm::mat4(1.0f), p); }

// A w x h quad facing +Z split into cells of about one unit: screendoor-object sizes its mask
// texels per triangle at the centroid's distance (Sen et al. 4.2.1), so a triangle that spans a
// wide range of distances gets texels far from one sample in size where it is near the eye.
Mesh makeGrid(float width, float height) {
    Mesh m;
    const int nx = std::max(1, int(std::ceil(width))), ny = std::max(1, int(std::ceil(height)));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            m.positions.push_back({width * (float(i) / nx - 0.5f), height * (float(j) / ny - 0.5f), 0.0f});
            m.normals.push_back({0, 0, 1});
        }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const std::uint32_t a = std::uint32_t(j * (nx + 1) + i), b = a + 1, c = a + std::uint32_t(nx + 1), d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    return m;
}

// Crow's opacity as crow.frag.glsl defines it (amin face-on, amax at the rim).
double crowAlpha(double nz, double amin, double amax, double p) {
    return amax - (amax - amin) * (1.0 - std::pow(1.0 - nz, p));
}

}  // namespace

TEST_CASE("crow matches its formula on a sphere") {
    // A black sphere over a white background: every pixel is the background times the
    // transmittance of the two surfaces the ray crosses, whatever order they blend in. The ray
    // enters and leaves a sphere at the same angle to the normal, so both have the same |N_z|
    // and the pixel is (1 - alpha(|N_z|))^2, with |N_z| from the analytic sphere.
    Scene s = emptyTestScene();
    const glm::vec3 centre(0.25f, -0.1f, -4.0f);
    place(s, makeSphere(1.0f, 128, 64), transparentMaterial(glm::vec3(0.0f), 0.5f), at(centre));
    test::Fixture f(std::move(s));
    const double amin = 0.2, amax = 0.9, p = 3.0;
    auto crow = test::makeTechnique("crow", {"amin=0.2", "amax=0.9", "p=3", "material_alpha=0"});
    const glm::ivec2 size(64, 64);
    Image image = test::renderWith(*f.gpu, f.camera, size, *crow).image;

    double maxError = 0.0;
    int inside = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const double nz = sphereFacing(x, y, size, f.camera.fovYDegrees, centre);
            const double got = image.at(x, y).r;
            // Near the rim the 128x64 tessellation's silhouette and normals depart from the
            // analytic sphere; the formula is checked where |N_z| >= 0.25.
            if (nz < 0.25) continue;
            double a = crowAlpha(nz, amin, amax, p);
            maxError = std::max(maxError, std::abs(got - (1.0 - a) * (1.0 - a)));
            ++inside;
        }
    MESSAGE("crow: " << inside << " pixels checked, largest error " << maxError);
    REQUIRE(inside > 500);
    // Interpolated normals of a 128x64 sphere are within ~1.4 degrees of the true ones, which
    // moves (1 - alpha)^2 by < 0.01 at p = 3; 8-bit nothing here (RGBA32F targets).
    CHECK(maxError < 0.01);
}

namespace {

const char* const kScreenDoorIds[] = {"screendoor", "screendoor-object", "screendoor-object-sw"};

// A quad of `alpha` facing the camera and filling the view, over a white background; a grid of
// unit cells, so no triangle passes screendoor-object-sw's per-triangle sample bound at n = 16.
Scene facingQuadScene(glm::vec3 color, float alpha) {
    Scene s = emptyTestScene();
    place(s, makeGrid(8.0f, 8.0f), transparentMaterial(color, alpha), at({0, 0, -2}));
    return s;
}

// Two overlapping quads and a sphere that crosses both: every pixel has 1 to 4 layers.
Scene overlappingScene() {
    Scene s = emptyTestScene();
    place(s, makeQuad(3.0f, 3.0f), transparentMaterial({0.9f, 0.2f, 0.1f}, 0.6f), at({-0.4f, 0.1f, -3.0f}));
    place(s, makeQuad(3.0f, 3.0f), transparentMaterial({0.1f, 0.3f, 0.9f}, 0.35f), at({0.5f, -0.2f, -3.6f}));
    place(s, makeSphere(0.9f, 32, 16), transparentMaterial({0.2f, 0.9f, 0.3f}, 0.5f), at({0.0f, 0.0f, -3.3f}));
    return s;
}

// 16x16 supersampling, and 256^2 masks where the technique has masks.
std::unique_ptr<Technique> at16x16(const std::string& id) {
    std::vector<std::string> settings{"supersampling=16"};
    if (test::hasSetting(id, "mask_size")) settings.push_back("mask_size=256");
    return test::makeTechnique(id, settings);
}

bool bitwiseEqual(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

double meanRed(const Image& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += image.at(x, y).r;
    return sum / (double(image.width) * image.height);
}

}  // namespace

TEST_CASE("screen-door techniques are registered as order-independent baselines") {
    for (const std::string id : {"crow", "screendoor", "screendoor-object", "screendoor-object-sw"}) {
        CAPTURE(id);
        const TechniqueEntry* e = findTechnique(id);
        REQUIRE(e != nullptr);
        CHECK(e->info.family == "baseline");
        CHECK_FALSE(e->info.robust);
    }
    for (const char* id : kScreenDoorIds)
        for (const char* name : {"supersampling", "seed"}) CHECK(test::hasSetting(id, name));
}

TEST_CASE("screen-door: mean opacity of a facing quad is its alpha at 16x16 supersampling") {
    // A black quad over white: each output pixel is 1 - (kept samples) / 256. The 16x16 output
    // at n = 16 holds K = 65536 samples. Each sample keeps or rejects by one mask texel, and
    // texels are independent Bernoulli(alpha') draws, alpha' = round(255 alpha) / 255. The 256^2
    // mask holds as many texels as there are samples: image space maps samples to texels one to
    // one; object space may land up to 4 samples on one texel (texels slightly larger than
    // samples off-axis, and the quad's two triangles share the mask), so the variance of the
    // mean is at most 4 alpha(1 - alpha) / K. Tolerance: 5 standard deviations of that,
    // sqrt(4 * 0.25 / 65536) * 5 = 0.0195 at alpha 0.5, plus the 8-bit quantization 0.5 / 255.
    // The images are deterministic (seeded), so the test is not flaky; 5 sigma makes a seed
    // that fails it a one-in-a-million draw.
    const glm::ivec2 size(16, 16);
    const double samples = double(size.x) * size.y * 256.0;
    for (float alpha : {0.25f, 0.5f, 0.8f}) {
        test::Fixture f(facingQuadScene(glm::vec3(0.0f), alpha));
        for (const std::string id : kScreenDoorIds) {
            CAPTURE(id);
            CAPTURE(alpha);
            auto technique = at16x16(id);
            test::Rendered r = test::renderWith(*f.gpu, f.camera, size, *technique);
            const double opacity = 1.0 - meanRed(r.image);
            const double tolerance = 5.0 * std::sqrt(4.0 * alpha * (1.0 - alpha) / samples) + 0.5 / 255.0;
            MESSAGE(id << " alpha " << alpha << ": mean opacity " << opacity << " (tolerance " << tolerance << ")");
            CHECK(std::abs(opacity - alpha) <= tolerance);
            // Fill, draw, four 2x2 averages (one tile); point sampling adds its compute pass.
            const int sampling = id == "screendoor-object-sw" ? 1 + r.result.stats.regrows : 0;
            CHECK(r.result.stats.passes == sampling + 1 + 1 + 4);
            CHECK(r.result.stats.objectDraws == 1);
            CHECK_FALSE(r.result.stats.overflowed);
        }
    }
}

TEST_CASE("screen-door: alpha 0 is invisible and alpha 1 opaque, exactly") {
    const glm::ivec2 size(12, 10);
    const glm::vec3 color(0.7f, 0.4f, 0.2f);  // lit head-on: the shaded colour is the base colour
    for (const std::string id : kScreenDoorIds) {
        CAPTURE(id);
        {
            test::Fixture f(facingQuadScene(color, 0.0f));
            Image image = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"supersampling=4"})).image;
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) CHECK(glm::vec3(image.at(x, y)) == glm::vec3(1.0f));
        }
        {
            test::Fixture f(facingQuadScene(color, 1.0f));
            Image image = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"supersampling=4"})).image;
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    glm::vec3 got(image.at(x, y));
                    CHECK(glm::all(glm::lessThanEqual(glm::abs(got - color), glm::vec3(1e-6f))));
                }
        }
    }
}

TEST_CASE("screen-door: the image does not depend on draw order, bit for bit") {
    test::Fixture f(overlappingScene());
    const glm::ivec2 size(24, 20);
    for (const std::string id : kScreenDoorIds) {
        CAPTURE(id);
        auto technique = test::makeTechnique(id, {"supersampling=8"});
        Image forward = test::renderWith(*f.gpu, f.camera, size, *technique).image;
        FrameOptions reversed;
        reversed.reverseSubmission = true;
        Image backward = test::renderWith(*f.gpu, f.camera, size, *technique, reversed).image;
        CHECK(bitwiseEqual(forward, backward));
        // ...and it is not the opaque image: something transparent was drawn.
        CHECK(meanRed(forward) < 0.99);
    }
}

TEST_CASE("screen-door: the same seed gives the same image bit for bit, another seed another image") {
    test::Fixture f(overlappingScene());
    const glm::ivec2 size(24, 20);
    for (const std::string id : kScreenDoorIds) {
        CAPTURE(id);
        Image first = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"seed=7"})).image;
        Image again = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"seed=7"})).image;
        Image other = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"seed=8"})).image;
        CHECK(bitwiseEqual(first, again));
        CHECK_FALSE(bitwiseEqual(first, other));
    }
}

namespace {

// Two tiles of samples: 160 x 6 pixels at n = 16 is 2560 samples wide, past the 2048 of one
// tile, so tiles of 128 and 32 columns, each drawn through its own projection. A black quad of
// `alpha` over white at depth 2, its centre `offset` world units right of NDC x `ndcX` (a pixel
// is 0.31088 world units there). The clip planes are set by hand: fitted to a large quad's
// sphere they would cut it off.
const glm::ivec2 kTwoTiles(160, 6);
test::Fixture twoTileScene(Mesh quad, float alpha, float ndcX, float offset = 0.0f) {
    const float depth = 2.0f;
    const float halfWidth = depth * std::tan(glm::radians(50.0f) / 2.0f) * float(kTwoTiles.x) / float(kTwoTiles.y);
    Scene s = emptyTestScene();
    place(s, std::move(quad), transparentMaterial(glm::vec3(0.0f), alpha), at({ndcX * halfWidth + offset, 0, -depth}));
    test::Fixture f(std::move(s));
    f.camera.nearPlane = 0.5f;
    f.camera.farPlane = 200.0f;
    return f;
}

}  // namespace

TEST_CASE("screen-door: a frame past one tile of samples renders in tiles that cover it") {
    // The two-tile frame, with a 100 x 8 quad whose left edge projects to column 120 (NDC 0.5)
    // across the seam: columns left of the edge stay white exactly; every column right of it
    // shows the quad at its alpha, within 5 standard deviations of one column's 6 * 256 samples
    // (at most 4 per texel, as in the flat-quad test): 0.13 at alpha 0.5. A tile drawn through
    // the whole frame's projection shows the edge at the wrong column.
    const float alpha = 0.5f;
    const glm::ivec2 size = kTwoTiles;
    test::Fixture f = twoTileScene(makeGrid(100.0f, 8.0f), alpha, 0.5f, 50.0f);
    for (const std::string id : kScreenDoorIds) {
        CAPTURE(id);
        auto technique = at16x16(id);
        test::Rendered r = test::renderWith(*f.gpu, f.camera, size, *technique);
        CHECK(r.result.stats.tiles == 2);
        const double tolerance = 5.0 * std::sqrt(4.0 * alpha * (1.0 - alpha) / (size.y * 256.0));
        for (int x = 0; x < size.x; ++x) {
            if (x == 119 || x == 120) continue;  // the edge column and its neighbour: partly covered
            double sum = 0.0;
            for (int y = 0; y < size.y; ++y) sum += r.image.at(x, y).r;
            const double opacity = 1.0 - sum / size.y;
            CAPTURE(x);
            if (x < 119) CHECK(opacity == 0.0);
            else CHECK(std::abs(opacity - alpha) <= tolerance);
        }
    }
}

TEST_CASE("screen-door: a tile the glass does not reach is not drawn, and shows the opaque colour") {
    // The two-tile frame with a 0.5 x 0.5 quad at NDC x 0.8: 1.6083 px a side. The cube around
    // its bounding sphere projects to columns 133-159, so the transparent area lies in the second
    // tile only: the first is skipped (one tile drawn) and stays the white background exactly.
    // The quad's opacity summed over the frame is alpha times its 2.5868 px^2, within 5 standard
    // deviations of its ~660 samples (0.25 px^2).
    const float alpha = 0.5f;
    test::Fixture f = twoTileScene(makeQuad(0.5f, 0.5f), alpha, 0.8f);
    for (const std::string id : kScreenDoorIds) {
        CAPTURE(id);
        auto technique = at16x16(id);
        test::Rendered r = test::renderWith(*f.gpu, f.camera, kTwoTiles, *technique);
        CHECK(r.result.stats.tiles == 1);
        double opacity = 0.0;
        for (int x = 0; x < kTwoTiles.x; ++x)
            for (int y = 0; y < kTwoTiles.y; ++y) {
                if (x < 128) {
                    CAPTURE(x);
                    CHECK(r.image.at(x, y).r == 1.0f);
                }
                opacity += 1.0 - r.image.at(x, y).r;
            }
        CHECK(std::abs(opacity - alpha * 2.5868) <= 0.25);
    }
}

TEST_CASE("silhouette opacity: the object-space methods grow opaque toward the rim, the stipple stays flat") {
    // A black sphere of alpha 0.3 over white: a pixel's opacity is 1 - its value. Both surfaces
    // a ray crosses meet it at the same |N_z|. The image-space stipple keeps alpha of the samples
    // per surface whatever the slope. Point sampling lays 1 / |N_z| points per sample where the
    // surface turns away, and the texture masks' footprint filter reads 1 / |N_z| texels per
    // sample, so near the rim (|N_z| in [0.2, 0.4], ~3 per sample a surface) both are clearly
    // more opaque than at the centre (|N_z| >= 0.8), where a surface is 1 - 0.7^2 = 0.51. Bins hold hundreds of pixels of 64 samples each, so
    // their means are good to ~0.01; the margins below are 5x that. The stipple keeps the same
    // samples on both surfaces of one object (one offset per object), so its back surface is
    // hidden and the sphere shows 0.3, not 0.51: the overlap artifact of the paper's Fig. 1.
    Scene s = emptyTestScene();
    const glm::vec3 centre(0.0f, 0.0f, -4.0f);
    place(s, makeSphere(1.0f, 96, 48), transparentMaterial(glm::vec3(0.0f), 0.3f), at(centre));
    test::Fixture f(std::move(s));
    const glm::ivec2 size(64, 64);
    for (const std::string id : kScreenDoorIds) {
        CAPTURE(id);
        Image image = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, {"supersampling=8"})).image;
        double sum[2] = {0, 0};
        int count[2] = {0, 0};
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const double nz = sphereFacing(x, y, size, f.camera.fovYDegrees, centre);
                int bin = nz >= 0.8 ? 0 : (nz >= 0.2 && nz <= 0.4) ? 1 : -1;
                if (bin < 0) continue;
                sum[bin] += 1.0 - image.at(x, y).r;
                ++count[bin];
            }
        REQUIRE(count[0] > 100);
        REQUIRE(count[1] > 100);
        const double centreOpacity = sum[0] / count[0], rimOpacity = sum[1] / count[1];
        MESSAGE(id << ": opacity at the centre " << centreOpacity << ", near the rim " << rimOpacity);
        CHECK(std::abs(centreOpacity - (id == "screendoor" ? 0.3 : 0.51)) < 0.05);
        if (id == "screendoor") CHECK(std::abs(rimOpacity - centreOpacity) < 0.05);
        else CHECK(rimOpacity > centreOpacity + 0.15);
    }
}

namespace {

// A width x height quad facing +Z as cells x cells squares, two triangles each.
Mesh makeFineGrid(float width, float height, int cells) {
    Mesh m;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            m.positions.push_back({width * (float(i) / cells - 0.5f), height * (float(j) / cells - 0.5f), 0.0f});
            m.normals.push_back({0, 0, 1});
        }
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const std::uint32_t a = std::uint32_t(j * (cells + 1) + i), b = a + 1, c = a + std::uint32_t(cells + 1), d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    return m;
}

// Supersampled pixels per scene unit at eye depth `depth` for an image `height` pixels tall at
// supersampling n (the camera's vertical field of view `fovYDegrees`).
double samplesPerUnit(int height, int n, double fovYDegrees, double depth) {
    return double(height) * n / (2.0 * depth * std::tan(glm::radians(fovYDegrees) / 2.0));
}

bool finiteUnit(const Image& image) {
    for (float v : image.rgba)
        if (!std::isfinite(v) || v < 0.0f || v > 1.0f) return false;
    return true;
}

}  // namespace

TEST_CASE("screen-door: triangles smaller than one sample still cover alpha of the surface") {
    // A 2 x 2 quad at depth 2 filling the 32x32 view, made of 200 x 200 cells: at n = 4 a sample
    // is 2 * 2 tan(25 deg) / 128 = 0.0146 units, so a cell is 0.69 samples wide and each triangle
    // covers 0.24 samples: most triangles hold no sample centre at all. The surface is still
    // covered once per sample: the rasterizer gives each sample centre to exactly one triangle of
    // the tessellation, and screendoor-object-sw's lattice is one per object (a phase per object,
    // axes from the camera), so each of its points falls in exactly one triangle and a face-on
    // surface gets one point per sample. Each sample is kept with probability alpha: as in the
    // flat-quad test, the mean over K = 32 * 32 * 16 = 16384 samples is alpha within 5 standard
    // deviations of at most 4 samples per texel, 5 sqrt(4 alpha (1 - alpha) / K) = 0.039 at
    // alpha 0.5, plus the 8-bit quantization of the mask levels. A technique that drops or
    // under-samples triangles smaller than a sample (a lattice that starts at each triangle's
    // own corner and rounds its point count down, a texel scale from the sub-sample edge) shows
    // far less.
    const int cells = 200;
    const glm::ivec2 size(32, 32);
    const int n = 4;
    const float alpha = 0.5f;
    Scene s = emptyTestScene();
    place(s, makeFineGrid(2.0f, 2.0f, cells), transparentMaterial(glm::vec3(0.0f), alpha), at({0, 0, -2}));
    test::Fixture f(std::move(s));
    const double cellSamples = 2.0 / cells * samplesPerUnit(size.y, n, f.camera.fovYDegrees, 2.0);
    REQUIRE(cellSamples < 0.75);
    const double samples = double(size.x) * size.y * n * n;
    const double tolerance = 5.0 * std::sqrt(4.0 * alpha * (1.0 - alpha) / samples) + 0.5 / 255.0;
    for (const std::string id : kScreenDoorIds) {
        CAPTURE(id);
        // One chunk of lattice points per triangle is plenty for sub-sample triangles.
        std::vector<std::string> settings{"supersampling=4"};
        if (id == "screendoor-object-sw") settings.push_back("max_triangle_samples=64");
        test::Rendered r = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, settings));
        REQUIRE(finiteUnit(r.image));
        const double opacity = 1.0 - meanRed(r.image);
        MESSAGE(id << ": " << 2 * cells * cells << " triangles of " << 0.5 * cellSamples * cellSamples
                   << " samples, mean opacity " << opacity << " (tolerance " << tolerance << ")");
        CHECK(std::abs(opacity - alpha) <= tolerance);
        CHECK_FALSE(r.result.stats.overflowed);
    }
}

TEST_CASE("screen-door: a triangle crossing the near plane and the eye plane draws what is in front, no NaN") {
    // A floor triangle 0.03 below the eye, from behind the eye (z = 0.5) to z = -6: it crosses
    // the eye plane, and the near plane (0.1) cuts it where the view sees it, at rows whose rays
    // meet the floor nearer than 0.1 (the bottom 18% of the image). Pixels whose whole footprint
    // (the rays through its four corners) misses the drawn part (above the horizon, beside the
    // triangle, or nearer than the near plane) stay exactly white; every value is finite and in
    // [0, 1]; pixels wholly inside are covered. The mask techniques keep alpha of the samples on
    // average: the mask is scaled for the centroid's depth (1.67), so near the near plane a texel
    // spans up to (1.67 / 0.1)^2 * |N_z| <= 81 samples (|N_z| <= 0.29 on this floor), and the mean
    // over the K covered samples is alpha within 5 sqrt(81 alpha (1 - alpha) / K). Point sampling
    // lays its lattice at the centroid's depth too, so it under-samples the floor nearer than the
    // centroid (fewer than one point per sample) and over-samples it beyond (silhouette opacity):
    // its coverage is checked against that expectation (below), not against alpha.
    const float alpha = 0.5f, floorY = -0.03f, nearPlane = 0.1f;
    const glm::vec3 a0(-3.0f, floorY, 0.5f), a1(3.0f, floorY, 0.5f), a2(0.0f, floorY, -6.0f);
    Mesh tri;
    tri.positions = {a0, a1, a2};
    tri.normals.assign(3, glm::vec3(0, 1, 0));
    tri.indices = {0, 1, 2};
    Scene s = emptyTestScene();
    place(s, std::move(tri), transparentMaterial(glm::vec3(0.0f), alpha), glm::mat4(1.0f));
    test::Fixture f(std::move(s));
    f.camera.nearPlane = nearPlane;
    f.camera.farPlane = 100.0f;
    const glm::ivec2 size(32, 32);
    const double t = std::tan(glm::radians(f.camera.fovYDegrees) / 2.0);
    // Whether the ray through image point (u, v) (pixel units) meets the drawn part of the triangle.
    auto drawn = [&](double u, double v) {
        const glm::dvec3 dir((u / size.x * 2.0 - 1.0) * t, (v / size.y * 2.0 - 1.0) * t, -1.0);
        if (dir.y >= 0.0) return false;
        const double depth = floorY / dir.y;  // eye depth: dir.z = -1
        if (depth < nearPlane || depth > f.camera.farPlane) return false;
        const glm::dvec2 p(dir.x * depth, -depth), b0(a0.x, a0.z), b1(a1.x, a1.z), b2(a2.x, a2.z);
        auto edge = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) { return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x); };
        const double e0 = edge(b0, b1, p), e1 = edge(b1, b2, p), e2 = edge(b2, b0, p);
        return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
    };
    std::vector<int> footprint(std::size_t(size.x) * size.y);  // 0 outside, 1 partly, 2 inside
    int inside = 0, outside = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const int hits = int(drawn(x, y)) + int(drawn(x + 1, y)) + int(drawn(x, y + 1)) + int(drawn(x + 1, y + 1));
            const int k = hits == 0 ? 0 : hits == 4 ? 2 : 1;
            footprint[std::size_t(y) * size.x + x] = k;
            inside += k == 2;
            outside += k == 0;
        }
    REQUIRE(inside > 150);
    REQUIRE(outside > 500);
    for (const std::string id : {"crow", "screendoor", "screendoor-object", "screendoor-object-sw"}) {
        CAPTURE(id);
        std::vector<std::string> settings;
        if (test::hasSetting(id, "supersampling")) settings.push_back("supersampling=4");
        test::Rendered r = test::renderWith(*f.gpu, f.camera, size, *test::makeTechnique(id, settings));
        REQUIRE(finiteUnit(r.image));
        double sum = 0.0;
        int leaks = 0, empty = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const double opacity = 1.0 - r.image.at(x, y).r;
                const int k = footprint[std::size_t(y) * size.x + x];
                if (k == 0 && opacity != 0.0) ++leaks;
                if (k != 2) continue;
                sum += opacity;
                if (opacity == 0.0) ++empty;
            }
        const double mean = sum / inside;
        MESSAGE(id << ": mean opacity inside " << mean << ", empty inside " << empty << ", drawn outside " << leaks
                   << ", overflow " << r.result.stats.overflowed);
        CHECK(leaks == 0);
        if (id == "crow") {
            // Crow: at most amax = 0.9 on one surface, at least the face-on alpha.
            CHECK(empty == 0);
            CHECK(mean >= alpha);
            CHECK(mean <= 0.9 + 1e-6);
        } else if (id != "screendoor-object-sw") {
            const double samples = double(inside) * 16.0;
            CHECK(std::abs(mean - alpha) <= 5.0 * std::sqrt(81.0 * alpha * (1.0 - alpha) / samples));
        } else {
            // The lattice (spacing one sample at the centroid's eye depth d_c = 5/3) seen at a
            // sample whose ray (dx, dy, -1) meets the floor at eye depth d: the sample's footprint
            // on the floor is d^2 / (s^2 |dy|) (s samples per unit at depth 1), the lattice holds
            // s^2 / d_c^2 points per unit area, so rho = d^2 / (d_c^2 |dy|) points fall in it. A
            // regular lattice puts floor(rho) or floor(rho) + 1 points in each sample, the second
            // in a fraction frac(rho) of them, each kept with probability alpha. The mean of that
            // over the covered samples is the expectation; tolerance 5 sqrt(0.25 / K) for the
            // kept draws plus 0.02 for rho varying across a sample (first order cancels).
            const double centroidDepth = 5.0 / 3.0;
            double predicted = 0.0;
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    if (footprint[std::size_t(y) * size.x + x] != 2) continue;
                    for (int j = 0; j < 4; ++j)
                        for (int i = 0; i < 4; ++i) {
                            const double dy = ((y + (j + 0.5) / 4.0) / size.y * 2.0 - 1.0) * t;
                            const double d = floorY / dy;
                            const double rho = d * d / (centroidDepth * centroidDepth * std::abs(dy));
                            const double k = std::floor(rho), frac = rho - k;
                            const double through = (1.0 - frac) * std::pow(1.0 - alpha, k) + frac * std::pow(1.0 - alpha, k + 1.0);
                            predicted += (1.0 - through) / 16.0;
                        }
                }
            predicted /= inside;
            MESSAGE(id << ": predicted from the lattice density " << predicted);
            CHECK(std::abs(mean - predicted) <= 5.0 * std::sqrt(0.25 / (16.0 * inside)) + 0.02);
        }
    }
}

TEST_CASE("screendoor-object-sw: a very large triangle gets a bounded lattice, counted as overflow") {
    // A 40 x 40 quad (two triangles) at depth 2, far larger than the 16x16 view at n = 16: at
    // s = 256 / (2 * 2 tan 25 deg) = 137.3 samples per unit each triangle wants 800 s^2 = 15.1M
    // lattice points, past max_triangle_samples = 2^18. Each gets a coarser lattice of that many:
    // spacing g = sqrt(15.1M / 2^18) = 7.6 samples, so the view's K = 256^2 samples hold K / g^2
    // = 1138 points, each kept with probability alpha, each on its own sample: mean opacity
    // alpha / g^2 = 0.0087 at alpha 0.5 instead of 0.5. Counted: both triangles bounded, overflow
    // set. Tolerance: the lattice axes follow the image's, so the view holds (256 / g +- 1)^2
    // points (+-6%), and the kept count is within 5 sqrt(1138 alpha (1 - alpha)) = 84 (7%): 15%.
    const float alpha = 0.5f;
    Scene s = emptyTestScene();
    place(s, makeQuad(40.0f, 40.0f), transparentMaterial(glm::vec3(0.0f), alpha), at({0, 0, -2}));
    test::Fixture f(std::move(s));
    f.camera.nearPlane = 0.5f;
    f.camera.farPlane = 10.0f;
    const glm::ivec2 size(16, 16);
    const int n = 16, bound = 1 << 18;
    const double perUnit = samplesPerUnit(size.y, n, f.camera.fovYDegrees, 2.0);
    const double wanted = 0.5 * 40.0 * 40.0 * perUnit * perUnit;
    REQUIRE(wanted > 16.0 * bound);
    const double spacing = std::sqrt(wanted / bound);
    const double expected = alpha / (spacing * spacing);
    auto technique = test::makeTechnique("screendoor-object-sw", {"supersampling=16", "max_triangle_samples=262144"});
    test::Rendered r = test::renderWith(*f.gpu, f.camera, size, *technique);
    REQUIRE(finiteUnit(r.image));
    const double opacity = 1.0 - meanRed(r.image);
    MESSAGE("lattice spacing " << spacing << " samples: mean opacity " << opacity << ", expected " << expected);
    CHECK(std::abs(opacity - expected) <= 0.15 * expected);
    CHECK(r.result.stats.primitivesBounded == 2);
    CHECK(r.result.stats.overflowed);
    CHECK(r.result.stats.fragmentsDropped == 0);
}

TEST_CASE("screendoor-object-sw: points past max_points_millions are counted, not stored") {
    // An 8 x 8 grid of unit cells (no triangle past the bound) at 32x32, n = 16: 274.5
    // samples per unit at depth 2, so 64 * 274.5^2 = 4.82M lattice points, 2.41M kept at
    // alpha 0.5, past the 2^20 points of max_points_millions = 1. The buffer grows once to
    // 2^20 and the rest are counted as dropped: kept - 2^20 = 1.36M. The kept count is off its
    // expectation by the lattice's boundary (+-1 point per row of each cell: 0.2%) and the draws
    // (5 sqrt(4.82M / 4) = 5500: 0.2%); checked within 1% of the kept count.
    const float alpha = 0.5f;
    const int n = 16;
    Scene grid = emptyTestScene();
    place(grid, makeGrid(8.0f, 8.0f), transparentMaterial(glm::vec3(0.0f), alpha), at({0, 0, -2}));
    test::Fixture g(std::move(grid));
    const glm::ivec2 gridSize(32, 32);
    const double gridPerUnit = samplesPerUnit(gridSize.y, n, g.camera.fovYDegrees, 2.0);
    const double kept = alpha * 64.0 * gridPerUnit * gridPerUnit;
    auto capped = test::makeTechnique("screendoor-object-sw", {"supersampling=16", "max_points_millions=1"});
    test::Rendered c = test::renderWith(*g.gpu, g.camera, gridSize, *capped);
    REQUIRE(finiteUnit(c.image));
    const double dropped = double(c.result.stats.fragmentsDropped);
    MESSAGE("kept points expected " << kept << ", dropped " << dropped << " past " << (1 << 20));
    CHECK(std::abs(dropped - (kept - double(1 << 20))) <= 0.01 * kept);
    CHECK(c.result.stats.overflowed);
    CHECK(c.result.stats.primitivesBounded == 0);
    CHECK(c.result.stats.regrows == 1);
}

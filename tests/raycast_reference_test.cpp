// The CPU ray-cast reference against closed forms: composited layers, exact edge ownership,
// coplanar ties, opaque occlusion, clipping, facing. Everything here is analytic; no goldens.
#include "camera/camera.hpp"
#include "reference/raycast.hpp"
#include "render/shading.hpp"
#include "scene/scene.hpp"

#include <doctest/doctest.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

using namespace strata;

namespace {

// The closed forms need no shading model: the test materials are unlit (KHR_materials_unlit:
// the base colour is the colour), except where a test is about the shading.
Scene emptyScene() {
    Scene s;
    s.materials.push_back(Material{});
    s.lightDirection = {0.0f, 0.0f, 1.0f};
    s.background = {0.1f, 0.2f, 0.3f};
    return s;
}

// Camera at the origin looking down -Z (the Camera convention), square pixels.
Camera originCamera(float fov = 50.0f, float nearPlane = 0.1f, float farPlane = 100.0f) {
    Camera c;
    c.position = glm::vec3(0.0f);
    c.orientation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    c.fovYDegrees = fov;
    c.nearPlane = nearPlane;
    c.farPlane = farPlane;
    return c;
}

// A square in the plane z = `z`, facing +Z (counter-clockwise seen from the camera), split by
// the diagonal (-h,-h)-(h,h) (or the other diagonal when `antiDiagonal`).
Mesh quad(float z, float h, bool antiDiagonal = false, bool flipWinding = false) {
    Mesh m;
    m.name = "quad";
    m.positions = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
    m.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    m.indices = antiDiagonal ? std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3} : std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3};
    if (flipWinding)
        for (std::size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
    return m;
}

// An axis-aligned box with outward counter-clockwise faces, one vertex set per face.
Mesh box(const glm::vec3& lo, const glm::vec3& hi) {
    Mesh m;
    m.name = "box";
    auto face = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
        auto base = std::uint32_t(m.positions.size());
        for (auto p : {a, b, c, d}) { m.positions.push_back(p); m.normals.push_back(n); }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
    };
    glm::vec3 l = lo, h = hi;
    face({l.x, l.y, h.z}, {h.x, l.y, h.z}, {h.x, h.y, h.z}, {l.x, h.y, h.z}, {0, 0, 1});
    face({h.x, l.y, l.z}, {l.x, l.y, l.z}, {l.x, h.y, l.z}, {h.x, h.y, l.z}, {0, 0, -1});
    face({h.x, l.y, h.z}, {h.x, l.y, l.z}, {h.x, h.y, l.z}, {h.x, h.y, h.z}, {1, 0, 0});
    face({l.x, l.y, l.z}, {l.x, l.y, h.z}, {l.x, h.y, h.z}, {l.x, h.y, l.z}, {-1, 0, 0});
    face({l.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, l.z}, {l.x, h.y, l.z}, {0, 1, 0});
    face({l.x, l.y, l.z}, {h.x, l.y, l.z}, {h.x, l.y, h.z}, {l.x, l.y, h.z}, {0, -1, 0});
    return m;
}

int addObject(Scene& s, Mesh mesh, const Material& material, const glm::mat4& local = glm::mat4(1.0f)) {
    mesh.material = s.addMaterial(material);
    int meshIndex = s.addMesh(std::move(mesh));
    Node n;
    n.local = local;
    n.meshes = {meshIndex};
    return s.addNode(n);
}

Material blend(glm::vec3 color, float alpha) {
    Material m;
    m.unlit = true;
    m.baseColor = color;
    m.alpha = alpha;
    m.alphaMode = AlphaMode::Blend;
    return m;
}

Material opaque(glm::vec3 color) {
    Material m;
    m.unlit = true;
    m.baseColor = color;
    return m;
}

void checkColor(const glm::vec4& got, const glm::vec3& want, double tol = 1e-5) {
    CHECK(std::abs(got.r - want.r) <= tol);
    CHECK(std::abs(got.g - want.g) <= tol);
    CHECK(std::abs(got.b - want.b) <= tol);
    CHECK(got.a == 1.0f);
}

struct Layer {
    float depth;
    glm::vec3 color;
    float alpha;
};

// The closed form, computed without the code under test: back to front, c = a L + (1 - a) c.
glm::vec3 closedForm(std::vector<Layer> layers, glm::vec3 background) {
    std::sort(layers.begin(), layers.end(), [](const Layer& a, const Layer& b) { return a.depth > b.depth; });
    glm::dvec3 c(background);
    for (const auto& l : layers) c = double(l.alpha) * glm::dvec3(l.color) + (1.0 - double(l.alpha)) * c;
    return glm::vec3(c);
}

}  // namespace

TEST_CASE("raycast: N full-screen layers composite to the closed form") {
    for (int n : {1, 2, 8}) {
        CAPTURE(n);
        Scene s = emptyScene();
        std::vector<Layer> layers;
        for (int i = 0; i < n; ++i) {
            // Declared in a scrambled depth order, so the reference has to sort.
            float depth = 2.0f + float((i * 5) % n);
            glm::vec3 color(0.1f + 0.1f * float(i), 0.9f - 0.1f * float(i), 0.5f);
            float alpha = 0.15f + 0.1f * float(i);
            layers.push_back({depth, color, alpha});
            addObject(s, quad(-depth, depth * 4.0f), blend(color, alpha));
        }
        auto objects = flatten(s);
        ReferenceStats stats;
        Image image = raycastReference(s, objects, originCamera(), 16, 12, &stats);
        glm::vec3 want = closedForm(layers, s.background);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) checkColor(image.at(x, y), want);
        CHECK(stats.fragments == std::size_t(16 * 12 * n));
        CHECK(stats.maxFragmentsPerPixel == n);
        CHECK(stats.tiedFragments == 0);
    }
}

TEST_CASE("raycast: two quads of alpha a1, a2") {
    const glm::vec3 c1(0.9f, 0.2f, 0.1f), c2(0.1f, 0.3f, 0.8f);
    for (auto [a1, a2] : {std::pair{0.5f, 0.5f}, {0.25f, 0.75f}, {1.0f, 0.3f}, {0.0f, 0.6f}}) {
        CAPTURE(a1);
        CAPTURE(a2);
        Scene s = emptyScene();
        addObject(s, quad(-5.0f, 20.0f), blend(c2, a2));  // far, declared first
        addObject(s, quad(-3.0f, 20.0f), blend(c1, a1));  // near
        auto objects = flatten(s);
        glm::vec3 bg = s.background;
        glm::vec3 want = a1 * c1 + (1.0f - a1) * (a2 * c2 + (1.0f - a2) * bg);
        Image image = raycastReference(s, objects, originCamera(), 8, 8);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) checkColor(image.at(x, y), want);
        auto frags = fragmentsAtPixel(s, objects, originCamera(), 8, 8, 3, 4);
        REQUIRE(frags.size() == 2);
        CHECK(frags[0].object == 1);  // the nearer one first
        CHECK(frags[0].depth == doctest::Approx(3.0).epsilon(1e-6));
        CHECK(frags[1].depth == doctest::Approx(5.0).epsilon(1e-6));
        CHECK(frags[0].frontFacing);
    }
}

TEST_CASE("raycast: a diagonal through pixel centres is counted exactly once") {
    // Square images: pixel centres with x == y lie exactly on the quad's diagonal. Every pixel
    // must get one fragment: zero would be a crack, two a double-blend seam.
    for (bool anti : {false, true}) {
        for (bool flip : {false, true}) {
            for (int size : {1, 3, 64, 65}) {
                CAPTURE(anti);
                CAPTURE(flip);
                CAPTURE(size);
                Scene s = emptyScene();
                addObject(s, quad(-4.0f, 4.0f * 2.0f, anti, flip), blend({1, 1, 1}, 0.5f));
                auto objects = flatten(s);
                RaycastReference ref(s, objects);
                Camera cam = originCamera();
                int bad = 0, ties = 0;
                for (int y = 0; y < size; ++y)
                    for (int x = 0; x < size; ++x) {
                        PixelSample p = ref.samplePixel(cam, size, size, x, y);
                        if (p.fragments.size() != 1) ++bad;
                        ties += p.edgeTieHits;
                    }
                CHECK(bad == 0);
                // Odd sizes put the centre pixel's ray on the view axis, where the diagonal's
                // edge function is exactly zero: the tie rule itself decides that pixel.
                if (size % 2 == 1) CHECK(ties >= 1);
            }
        }
    }
}

TEST_CASE("raycast: a fan of triangles around the view axis gives one fragment") {
    // Eight triangles share the vertex on the view axis: the centre ray hits all of them on
    // the shared vertex (two edge functions zero) and must be counted once.
    Scene s = emptyScene();
    Mesh fan;
    fan.positions.push_back({0.0f, 0.0f, -2.0f});
    for (int i = 0; i < 8; ++i) {
        float a = float(i) * glm::pi<float>() / 4.0f;
        fan.positions.push_back({10.0f * std::cos(a), 10.0f * std::sin(a), -2.0f});
    }
    for (std::uint32_t i = 0; i < 8; ++i) {
        fan.indices.insert(fan.indices.end(), {0u, 1 + i, 1 + (i + 1) % 8});
    }
    fan.normals.assign(fan.positions.size(), glm::vec3(0, 0, 1));
    addObject(s, fan, blend({1, 0, 0}, 0.5f));
    auto objects = flatten(s);
    RaycastReference ref(s, objects);
    for (int size : {1, 3, 5, 33}) {
        CAPTURE(size);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) CHECK(ref.samplePixel(originCamera(), size, size, x, y).fragments.size() == 1);
    }
    CHECK(ref.samplePixel(originCamera(), 1, 1, 0, 0).edgeTieHits == 1);
}

TEST_CASE("raycast: a bumpy grid is watertight for rays through its vertices and edges") {
    // Dyadic vertices and ray directions make the ray-space coordinates exact, so many rays run
    // exactly through vertices and edges (edge functions exactly 0). Each must hit once.
    Scene s = emptyScene();
    Mesh grid;
    const int n = 8;  // 8x8 cells over [-1, 1]^2, spacing 1/4
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            float z = -1.0f - float((i * 7 + j * 3) % 4) / 64.0f;  // small bumps keep one hit per ray
            grid.positions.push_back({-1.0f + float(i) / 4.0f, -1.0f + float(j) / 4.0f, z});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            std::uint32_t a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + n + 2, d = a + n + 1;
            if ((i + j) % 2) grid.indices.insert(grid.indices.end(), {a, b, c, a, c, d});
            else grid.indices.insert(grid.indices.end(), {a, b, d, b, c, d});
        }
    grid.normals.assign(grid.positions.size(), glm::vec3(0, 0, 1));
    addObject(s, grid, blend({0, 1, 0}, 0.5f));
    auto objects = flatten(s);
    RaycastReference ref(s, objects);
    int ties = 0, bad = 0;
    for (int j = -7 * 4; j <= 7 * 4; ++j)
        for (int i = -7 * 4; i <= 7 * 4; ++i) {
            PixelSample p = ref.sampleRay({0, 0, 0}, {double(i) / 32.0, double(j) / 32.0, -1.0}, 0.01, 10.0);
            if (p.fragments.size() != 1) ++bad;
            ties += p.edgeTieHits;
        }
    CHECK(bad == 0);
    CHECK(ties > 50);
}

TEST_CASE("raycast: a closed box is crossed an even number of times, silhouettes included") {
    Scene s = emptyScene();
    addObject(s, box({-0.5f, -0.5f, -4.0f}, {0.5f, 0.5f, -2.0f}), blend({1, 1, 0}, 0.3f));
    auto objects = flatten(s);
    RaycastReference ref(s, objects);
    // Dyadic directions i/32 run exactly through the front face's silhouette edges and corners
    // (x / -z = 0.25) and the back face's (0.125), and through the diagonals of both faces.
    int odd = 0, two = 0;
    for (int j = -12; j <= 12; ++j)
        for (int i = -12; i <= 12; ++i) {
            PixelSample p = ref.sampleRay({0, 0, 0}, {double(i) / 32.0, double(j) / 32.0, -1.0}, 0.01, 10.0);
            if (p.fragments.size() % 2) ++odd;
            if (p.fragments.size() == 2) ++two;
        }
    CHECK(odd == 0);
    CHECK(two > 0);
    // The same from oblique cameras over whole images.
    for (glm::vec3 eye : {glm::vec3(1.5f, 1.0f, 0.0f), glm::vec3(-2.0f, 0.3f, -1.0f), glm::vec3(0.0f, 4.0f, -3.0f)}) {
        Camera cam = originCamera();
        cam.lookAt(eye, {0.0f, 0.0f, -3.0f});
        cam.farPlane = 20.0f;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) CHECK(ref.samplePixel(cam, 32, 32, x, y).fragments.size() % 2 == 0);
    }
}

TEST_CASE("raycast: K coincident copies give K fragments with identical depth, by object id") {
    for (int k : {2, 3, 8}) {
        CAPTURE(k);
        Scene s = emptyScene();
        // Same mesh and the same non-trivial world transform in every copy.
        glm::mat4 world = glm::rotate(glm::translate(glm::mat4(1.0f), {0.1f, -0.2f, -3.0f}), 0.4f, {0.3f, 1.0f, 0.2f});
        Mesh m = box({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
        for (int i = 0; i < k; ++i) addObject(s, m, blend({0.2f * float(i), 0.5f, 0.5f}, 0.4f), world);
        auto objects = flatten(s);
        RaycastReference ref(s, objects);
        PixelSample p = ref.samplePixel(originCamera(), 9, 9, 4, 4);
        REQUIRE(p.fragments.size() == std::size_t(2 * k));  // entry and exit of each copy
        for (int i = 0; i < k; ++i) {
            CHECK(p.fragments[i].depth == p.fragments[0].depth);  // bit-identical
            CHECK(p.fragments[i].object == i);
            CHECK(p.fragments[k + i].depth == p.fragments[k].depth);
            CHECK(p.fragments[k + i].object == i);
        }
        CHECK(p.fragments[0].depth < p.fragments[k].depth);
        CHECK(p.depthTies == 2 * (k - 1));
        ReferenceStats stats;
        ref.render(originCamera(), 9, 9, &stats);
        CHECK(stats.pixelsWithTies == stats.pixelsWithFragments);
        CHECK(stats.coplanarityProbability() == 1.0);
    }
}

TEST_CASE("raycast: opaque surfaces hide what is behind them") {
    const glm::vec3 red(0.9f, 0.1f, 0.1f), blue(0.1f, 0.1f, 0.9f), grey(0.5f);
    SUBCASE("opaque in front of transparent") {
        Scene s = emptyScene();
        addObject(s, quad(-5.0f, 20.0f), blend(red, 0.5f));
        addObject(s, quad(-3.0f, 20.0f), opaque(grey));
        auto objects = flatten(s);
        PixelSample p = samplePixel(s, objects, originCamera(), 4, 4, 1, 2);
        CHECK(p.fragments.empty());
        CHECK(p.hasOpaque);
        CHECK(p.opaqueObject == 1);
        checkColor(glm::vec4(p.color, 1.0f), grey);
    }
    SUBCASE("transparent in front of opaque composites over it") {
        Scene s = emptyScene();
        addObject(s, quad(-5.0f, 20.0f), opaque(grey));
        addObject(s, quad(-3.0f, 20.0f), blend(red, 0.25f));
        auto objects = flatten(s);
        Image image = raycastReference(s, objects, originCamera(), 4, 4);
        checkColor(image.at(2, 2), 0.25f * red + 0.75f * grey);
    }
    SUBCASE("transparent at the opaque depth is hidden (strictly nearer only)") {
        Scene s = emptyScene();
        addObject(s, quad(-4.0f, 20.0f), opaque(grey));
        addObject(s, quad(-4.0f, 20.0f), blend(red, 0.5f));
        auto objects = flatten(s);
        CHECK(samplePixel(s, objects, originCamera(), 4, 4, 0, 0).fragments.empty());
    }
    SUBCASE("coplanar opaque surfaces: the lower object id wins") {
        Scene s = emptyScene();
        addObject(s, quad(-4.0f, 20.0f), opaque(blue));
        addObject(s, quad(-4.0f, 20.0f), opaque(red));
        auto objects = flatten(s);
        PixelSample p = samplePixel(s, objects, originCamera(), 4, 4, 3, 1);
        CHECK(p.opaqueObject == 0);
        checkColor(glm::vec4(p.color, 1.0f), blue);
    }
    SUBCASE("MASK below its cutoff is discarded, above it is opaque") {
        Scene s = emptyScene();
        addObject(s, quad(-6.0f, 20.0f), blend(red, 0.5f));
        Material cut = opaque(blue);
        cut.alphaMode = AlphaMode::Mask;
        cut.alpha = 0.3f;
        cut.alphaCutoff = 0.5f;
        addObject(s, quad(-4.0f, 20.0f), cut);
        auto objects = flatten(s);
        PixelSample p = samplePixel(s, objects, originCamera(), 4, 4, 1, 1);
        CHECK(p.fragments.size() == 1);
        CHECK_FALSE(p.hasOpaque);
        s.materials[2].alpha = 0.7f;
        p = samplePixel(s, objects, originCamera(), 4, 4, 1, 1);
        CHECK(p.fragments.empty());
        CHECK(p.hasOpaque);
    }
    SUBCASE("nothing at all gives the background") {
        Scene s = emptyScene();
        auto objects = flatten(s);
        checkColor(raycastReference(s, objects, originCamera(), 2, 2).at(1, 1), s.background);
    }
}

TEST_CASE("raycast: hits are clipped to [near, far] in eye depth") {
    Scene s = emptyScene();
    addObject(s, quad(-0.5f, 10.0f), blend({1, 0, 0}, 0.5f));   // before near = 1
    addObject(s, quad(-2.0f, 10.0f), blend({0, 1, 0}, 0.5f));   // inside
    addObject(s, quad(-20.0f, 100.0f), opaque({0, 0, 1}));       // beyond far = 10
    auto objects = flatten(s);
    Camera cam = originCamera(50.0f, 1.0f, 10.0f);
    RaycastReference ref(s, objects);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            PixelSample p = ref.samplePixel(cam, 8, 8, x, y);
            REQUIRE(p.fragments.size() == 1);
            CHECK(p.fragments[0].object == 1);
            // Eye depth, not ray length: equal across the image for a plane facing the camera.
            CHECK(p.fragments[0].depth == doctest::Approx(2.0).epsilon(1e-6));
            CHECK_FALSE(p.hasOpaque);
        }
    cam.farPlane = 30.0f;
    CHECK(ref.samplePixel(cam, 8, 8, 0, 0).hasOpaque);
}

TEST_CASE("raycast: pixel rows start at the bottom and rays match the projection") {
    Scene s = emptyScene();
    // Covers only the upper-right quadrant of the view.
    Mesh m = quad(-3.0f, 10.0f);
    for (auto& p : m.positions) p = glm::max(p, glm::vec3(0.0f, 0.0f, -3.0f));
    addObject(s, m, blend({1, 1, 1}, 1.0f));
    auto objects = flatten(s);
    Camera cam = originCamera();
    RaycastReference ref(s, objects);
    const int w = 12, h = 8;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            bool inside = x >= w / 2 && y >= h / 2;
            CHECK(ref.samplePixel(cam, w, h, x, y).fragments.size() == (inside ? 1u : 0u));
        }
    // A point along any pixel ray projects back to that pixel's centre through the GPU matrices.
    Camera tilted = originCamera(70.0f);
    tilted.lookAt({1.0f, 2.0f, 3.0f}, {-0.5f, 0.0f, -1.0f});
    glm::mat4 vp = tilted.projection(float(w) / float(h)) * tilted.view();
    for (auto [x, y] : {std::pair{0, 0}, {11, 7}, {5, 2}}) {
        glm::dvec3 o, d;
        pixelRay(tilted, w, h, x, y, o, d);
        CHECK(glm::dot(d, glm::dvec3(tilted.forward())) == doctest::Approx(1.0).epsilon(1e-6));
        glm::vec4 clip = vp * glm::vec4(glm::vec3(o + 7.0 * d), 1.0f);
        CHECK((clip.x / clip.w * 0.5 + 0.5) * w == doctest::Approx(x + 0.5).epsilon(1e-4));
        CHECK((clip.y / clip.w * 0.5 + 0.5) * h == doctest::Approx(y + 0.5).epsilon(1e-4));
        CHECK(clip.w == doctest::Approx(7.0).epsilon(1e-5));  // eye depth is the ray parameter
    }
}

TEST_CASE("raycast: camera inside a box sees its back faces, one per pixel") {
    for (bool mirrored : {false, true}) {
        CAPTURE(mirrored);
        Scene s = emptyScene();
        // A mirroring world reverses the winding on screen; the front face must stay the
        // object-space counter-clockwise one (glTF), so the inside still reads as back faces.
        glm::mat4 world = mirrored ? glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f}) : glm::mat4(1.0f);
        addObject(s, box({-2, -2, -2}, {2, 2, 2}), blend({0.3f, 0.6f, 0.9f}, 0.5f), world);
        auto objects = flatten(s);
        RaycastReference ref(s, objects);
        Camera cam = originCamera(90.0f);
        cam.lookAt({0.2f, -0.1f, 0.3f}, {1.0f, 0.5f, -1.0f});
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                PixelSample p = ref.samplePixel(cam, 16, 16, x, y);
                REQUIRE(p.fragments.size() == 1);
                CHECK_FALSE(p.fragments[0].frontFacing);
            }
    }
}

TEST_CASE("raycast: facing and single-sided culling") {
    Scene s = emptyScene();
    Material m = blend({1, 0, 0}, 0.5f);
    addObject(s, quad(-3.0f, 10.0f, false, /*flipWinding=*/true), m);  // seen from behind
    auto objects = flatten(s);
    auto p = samplePixel(s, objects, originCamera(), 4, 4, 2, 2);
    REQUIRE(p.fragments.size() == 1);
    CHECK_FALSE(p.fragments[0].frontFacing);
    s.materials.back().doubleSided = false;
    // By default every face is kept, as the GPU pipeline draws with culling off.
    CHECK(samplePixel(s, objects, originCamera(), 4, 4, 2, 2).fragments.size() == 1);
    RaycastOptions cull;
    cull.cullSingleSidedBackFaces = true;
    CHECK(RaycastReference(s, objects, cull).samplePixel(originCamera(), 4, 4, 2, 2).fragments.empty());
    // A front face of a single-sided material survives culling.
    Scene front = emptyScene();
    addObject(front, quad(-3.0f, 10.0f), m);
    front.materials.back().doubleSided = false;
    auto frontObjects = flatten(front);
    CHECK(RaycastReference(front, frontObjects, cull).samplePixel(originCamera(), 4, 4, 2, 2).fragments.size() == 1);
}

TEST_CASE("raycast: normals are interpolated and follow the inverse transpose") {
    Scene s = emptyScene();
    s.lightDirection = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
    Mesh m = quad(-3.0f, 10.0f);
    // Object-space normal tilted in x; a non-uniform scale in x must tilt it the other way
    // (inverse transpose), not along with the geometry.
    m.normals.assign(4, glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f)));
    Material lit = opaque({1, 1, 1});
    lit.unlit = false;
    addObject(s, m, lit, glm::scale(glm::mat4(1.0f), {4.0f, 1.0f, 1.0f}));
    auto objects = flatten(s);
    glm::vec3 n = glm::normalize(glm::vec3(1.0f / 4.0f, 0.0f, 1.0f));
    glm::dvec3 origin, direction;
    pixelRay(originCamera(), 4, 4, 1, 3, origin, direction);
    const glm::vec3 toEye(-glm::normalize(direction));
    const glm::vec3 want = shadeSurface(glm::vec3(1.0f), 0.0f, 1.0f, 1.0f, glm::vec3(0.0f), n, toEye, s.lightDirection,
                                        glm::vec3(kDefaultLightIrradiance));
    checkColor(raycastReference(s, objects, originCamera(), 4, 4).at(1, 3), want);
    // The tilt is visible: the untransformed normal would shade otherwise.
    const glm::vec3 untilted = shadeSurface(glm::vec3(1.0f), 0.0f, 1.0f, 1.0f, glm::vec3(0.0f), glm::normalize(glm::vec3(1, 0, 1)),
                                            toEye, s.lightDirection, glm::vec3(kDefaultLightIrradiance));
    CHECK(std::abs(untilted.r - want.r) > 0.01f);
}

TEST_CASE("raycast: a 70k-triangle closed sphere renders quickly and stays watertight") {
    Scene s = emptyScene();
    Mesh sphere;
    const int rings = 176, segments = 200;  // ~70k triangles, like the Stanford bunny
    sphere.positions.push_back({0, 1, 0});
    for (int r = 1; r < rings; ++r)
        for (int g = 0; g < segments; ++g) {
            float th = glm::pi<float>() * float(r) / rings, ph = 2.0f * glm::pi<float>() * float(g) / segments;
            sphere.positions.push_back({std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)});
        }
    sphere.positions.push_back({0, -1, 0});
    auto ring = [&](int r, int g) { return std::uint32_t(1 + (r - 1) * segments + (g % segments)); };
    const auto south = std::uint32_t(sphere.positions.size() - 1);
    for (int g = 0; g < segments; ++g) {
        sphere.indices.insert(sphere.indices.end(), {0u, ring(1, g + 1), ring(1, g)});
        sphere.indices.insert(sphere.indices.end(), {south, ring(rings - 1, g), ring(rings - 1, g + 1)});
        for (int r = 1; r + 1 < rings; ++r) {
            std::uint32_t a = ring(r, g), b = ring(r, g + 1), c = ring(r + 1, g + 1), d = ring(r + 1, g);
            sphere.indices.insert(sphere.indices.end(), {a, b, c, a, c, d});
        }
    }
    sphere.normals = sphere.positions;
    addObject(s, sphere, blend({0.8f, 0.7f, 0.6f}, 0.5f), glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -3.0f}));
    auto objects = flatten(s);
    auto start = std::chrono::steady_clock::now();
    RaycastReference ref(s, objects);
    CHECK(ref.triangleCount() > 69000);
    Camera cam = originCamera();
    ReferenceStats stats;
    Image image = ref.render(cam, 64, 64, &stats);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    MESSAGE("70k-triangle sphere, BVH build + 64x64 reference: " << ms << " ms");
    CHECK(stats.maxFragmentsPerPixel == 2);
    int odd = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            if (ref.samplePixel(cam, 64, 64, x, y).fragments.size() % 2) ++odd;
    CHECK(odd == 0);
}

// The on-disk impostor cache (lod/impostor_cache.hpp): an impostor read back equals the one
// baked (texels, rectangles, quads, hole slices, memory); the key follows the content and the
// settings; a damaged file is removed and counted, never read as an impostor; the folder keeps
// to its cap, least recently used first; and a second LOD controller on the same scene loads
// what the first baked, and then finds its impostors worth using over one frame. And the memory
// cap on impostors held: the most useful kept, the rest skipped or evicted.
#include "gl_test_support.hpp"

#include "lod/impostor_cache.hpp"
#include "lod/lod_cost_cache.hpp"
#include "lod/impostor_set.hpp"
#include "lod/lod_controller.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh_builders.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <fstream>
#include <thread>
#include <tuple>

using namespace strata;
using namespace strata::lod;
namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> texelsOf(GLuint texture, const LayeredImpostor& imp) {
    const ImpostorSettings& s = imp.settings();
    std::vector<std::uint8_t> texels(std::size_t(s.resolution) * std::size_t(s.resolution) * 4u * std::size_t(s.views * s.peels));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(texels.size()), texels.data());
    return texels;
}

ImpostorSettings small() {
    ImpostorSettings s;
    s.views = 12;
    s.resolution = 32;
    s.slices = 8;
    return s;
}

// A folder of its own under the system's temporary folder, removed at the end.
struct TempFolder {
    fs::path path;
    explicit TempFolder(const char* name) : path(fs::temp_directory_path() / (std::string("strata-test-") + name)) {
        fs::remove_all(path);
    }
    ~TempFolder() { fs::remove_all(path); }
};

LodOptions cachedImpostors(LodMode mode, const fs::path& folder) {
    LodOptions o;
    o.mode = mode;
    o.impostor = small();
    o.impostorCache = folder;
    return o;
}

}  // namespace

TEST_CASE("impostor cache: what is read back equals what was baked") {
    test::Fixture fx(makeFieldScene(2, false));
    const int mesh = fx.gpu->objects()[1].mesh;
    for (int peels : {1, 2}) {
        ImpostorSettings s = small();
        s.peels = peels;
        s.slices = 16;  // two levels: 16 and 8 merged
        s.mergedLevels = true;
        const LayeredImpostor baked(fx.gpu->meshOf(1), fx.gpu->scene().meshes[std::size_t(mesh)].bounds(), s);
        REQUIRE(baked.valid());
        const std::vector<std::uint8_t> bytes = baked.serialize();
        const LayeredImpostor loaded = LayeredImpostor::deserialize(bytes, true);
        // The levels are no part of the file: a load that does not ask has the baked slices alone.
        CHECK(LayeredImpostor::deserialize(bytes).levels() == 1);
        gl::checkGl("impostor load");
        REQUIRE(loaded.valid());
        CHECK(loaded.settings().peels == peels);
        CHECK(loaded.quadCount() == baked.quadCount());
        CHECK(loaded.bytes().total() == baked.bytes().total());
        CHECK(loaded.centre() == baked.centre());
        CHECK(loaded.radius() == baked.radius());
        CHECK(texelsOf(loaded.atlas(), loaded) == texelsOf(baked.atlas(), baked));
        // Every level of merged slices, rebuilt from the loaded images, as baked.
        REQUIRE(loaded.levels() == baked.levels());
        CHECK(baked.levels() > 1);
        for (int level = 0; level < baked.levels(); ++level) {
            CAPTURE(level);
            CHECK(loaded.quadCount(level) == baked.quadCount(level));
            for (int view = 0; view < s.views; ++view)
                for (int slice = 0; slice < baked.levelSlices(level); ++slice) {
                    const SliceRect a = loaded.rectangle(view, 0, slice, level), b = baked.rectangle(view, 0, slice, level);
                    REQUIRE(std::tie(a.x0, a.y0, a.x1, a.y1) == std::tie(b.x0, b.y0, b.x1, b.y1));
                    REQUIRE(loaded.sliceRange(view, 0, slice, level) == baked.sliceRange(view, 0, slice, level));
                }
            for (const auto& [v, w] : baked.adjacency())
                CHECK(loaded.holeSlices(v, w, level) == baked.holeSlices(v, w, level));
            // The same draws for an eye anywhere.
            const glm::vec3 eye = baked.centre() + glm::vec3(3.0f, 1.0f, 2.0f) * baked.radius();
            const StandInDraw a = baked.drawFor(eye, true, level), b = loaded.drawFor(eye, true, level);
            CHECK(a.first == b.first);
            CHECK(a.count == b.count);
            CHECK(a.slices == baked.levelSlices(level));
        }
        CHECK(loaded.adjacency() == baked.adjacency());
        // Serialising what was loaded gives the same bytes.
        CHECK(loaded.serialize() == bytes);
    }
}

TEST_CASE("impostor cache: malformed bytes are refused with the reason, never read as an impostor") {
    test::Fixture fx(makeFieldScene(2, false));
    const LayeredImpostor baked(fx.gpu->meshOf(1), fx.gpu->scene().meshes[std::size_t(fx.gpu->objects()[1].mesh)].bounds(), small());
    const std::vector<std::uint8_t> bytes = baked.serialize();
    auto error = [](std::vector<std::uint8_t> b) {
        try {
            LayeredImpostor::deserialize(b);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(error({}) == "ends inside the header");
    // 13 bytes of header, 25 of settings, 17 of bounds and flag: byte 60 is inside the atlas.
    CHECK(error(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 60)) == "ends inside the atlas");
    CHECK(error(std::vector<std::uint8_t>(bytes.begin(), bytes.end() - 1)) != "no error");
    std::vector<std::uint8_t> longer = bytes;
    longer.push_back(0);
    CHECK(error(longer) == "bytes after the end");
    std::vector<std::uint8_t> version = bytes;
    version[9] = 99;  // the version follows the 9-byte magic
    CHECK(error(version) == "impostor file version 99, expected 1");
    std::vector<std::uint8_t> views = bytes;
    views[13] = 7;  // views: 12 -> 7
    CHECK(error(views) == "impostor views must be 12, 20 or 32, not 7");
    std::vector<std::uint8_t> magic = bytes;
    magic[0] = 'X';
    CHECK(error(magic) == "not an impostor file");
}

TEST_CASE("impostor cache: keys follow content and settings; hits, misses, damaged files, the cap") {
    test::Fixture fx(makeFieldScene(2, false));
    const Scene& scene = fx.gpu->scene();
    const int mesh = fx.gpu->objects()[1].mesh;
    const std::uint64_t key = impostorKey(scene, mesh, small(), {});
    CHECK(impostorKey(scene, mesh, small(), {}) == key);
    ImpostorSettings finer = small();
    finer.slices = 9;
    CHECK(impostorKey(scene, mesh, finer, {}) != key);
    Scene moved = scene;
    moved.meshes[std::size_t(mesh)].positions[0].x += 1e-3f;
    CHECK(impostorKey(moved, mesh, small(), {}) != key);
    // Another mesh (the ground) has its own key.
    int other = -1;
    for (const auto& o : fx.gpu->objects())
        if (o.mesh != mesh) other = o.mesh;
    REQUIRE(other >= 0);
    CHECK(impostorKey(scene, other, small(), {}) != key);

    TempFolder folder("impostor-cache");
    ImpostorCache cache(folder.path);
    CHECK_FALSE(cache.load(key));
    CHECK(cache.counts().misses == 1);
    const LayeredImpostor baked(fx.gpu->meshOf(1), scene.meshes[std::size_t(mesh)].bounds(), small());
    REQUIRE(cache.store(key, baked));
    CHECK(cache.contains(key));
    CHECK(fs::file_size(cache.pathOf(key)) == baked.serialize().size());
    const std::optional<LayeredImpostor> hit = cache.load(key);
    REQUIRE(hit);
    CHECK(hit->quadCount() == baked.quadCount());
    CHECK(cache.counts().hits == 1);
    CHECK(cache.counts().stores == 1);

    // A damaged file: removed, counted, a miss.
    fs::resize_file(cache.pathOf(key), 100);
    CHECK_FALSE(cache.load(key));
    CHECK(cache.counts().unreadable == 1);
    CHECK_FALSE(fs::exists(cache.pathOf(key)));

    // A cap of one and a half files: storing a second removes the least recently used.
    const std::uint64_t size = baked.serialize().size();
    ImpostorCache capped(folder.path, size + size / 2);
    REQUIRE(capped.store(1, baked));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // distinct modification times
    REQUIRE(capped.store(2, baked));
    CHECK(capped.counts().evicted == 1);
    CHECK_FALSE(capped.contains(1));
    CHECK(capped.contains(2));
}

TEST_CASE("impostor cache: a second controller loads what the first baked, and over one frame it pays") {
    test::Fixture fx(makeFieldScene(4, false));
    TempFolder folder("impostor-cache-controller");
    // Forced impostors bake once, store every impostor the frame uses.
    int baked = 0;
    {
        LodController first(*fx.gpu, cachedImpostors(LodMode::Impostors, folder.path));
        first.select(fx.camera, {64, 48});
        REQUIRE(first.impostors());
        baked = first.impostors()->bakedImpostors();
        REQUIRE(baked > 0);
        CHECK(first.impostors()->loadedImpostors() == 0);
        REQUIRE(first.cache());
        CHECK(first.cache()->counts().stores == baked);
    }
    // Auto over one frame with a model under which a bake never pays (the planned-frames test's):
    // without the cache it bakes nothing; with it, loading costs nothing and the impostors are used.
    LodCostModel device;
    device.geometryMsPerMegatriangle = 100.0;
    device.impostorMsPerMegapixel = 1.0;
    LodOptions once = cachedImpostors(LodMode::Auto, {});
    once.plannedFrames = 1;
    once.costModel = device;
    {
        LodController uncached(*fx.gpu, once);
        uncached.select(fx.camera, {64, 48});
        CHECK(uncached.bakeDecisions().declined == 1);
    }
    once.impostorCache = folder.path;
    LodController second(*fx.gpu, once);
    second.select(fx.camera, {64, 48});
    CHECK(second.bakeDecisions().declined == 0);
    REQUIRE(second.impostors());
    CHECK(second.impostors()->loadedImpostors() == 1);  // the instances' one shared impostor
    CHECK(second.cache()->counts().hits == 1);
    CHECK(second.cache()->counts().stores == 0);
    CHECK(second.selection().impostorObjects > 0);

    // Evicted (here: the folder emptied), the impostor is baked again and stored again.
    for (const auto& e : fs::directory_iterator(folder.path)) fs::remove(e.path());
    LodController third(*fx.gpu, cachedImpostors(LodMode::Impostors, folder.path));
    third.select(fx.camera, {64, 48});
    REQUIRE(third.impostors());
    CHECK(third.impostors()->loadedImpostors() == 0);
    CHECK(third.impostors()->bakedImpostors() == baked);
    CHECK(third.cache()->counts().misses == baked);
    CHECK(third.cache()->counts().stores == baked);
}

TEST_CASE("impostor memory cap: the more useful impostor is baked, the other evicted or skipped, its object geometry") {
    // Two distinct meshes side by side, far from the eye: a dense sphere (more triangles, so more
    // geometry time saved) and a box, each its own impostor of the same predicted size.
    Scene s;
    s.name = "two-meshes";
    s.materials = {Material{}};
    auto place = [&](Mesh mesh, glm::vec3 at) {
        Node node;
        node.local = glm::translate(glm::mat4(1.0f), at);
        node.meshes = {s.addMesh(std::move(mesh))};
        s.addNode(node);
    };
    place(makeSphere(1.0f, 96, 48), {-1.5f, 0.0f, 0.0f});
    place(makeBox(glm::vec3(-1.0f), glm::vec3(1.0f)), {1.5f, 0.0f, 0.0f});
    test::Fixture fx(std::move(s));
    Camera far = fx.camera;
    far.position = glm::vec3(0.0f, 0.0f, 40.0f);
    far.fitClipPlanes(fx.gpu->bounds());
    LodOptions o = cachedImpostors(LodMode::Impostors, {});
    LodController all(*fx.gpu, o);
    all.select(far, {64, 48});
    REQUIRE(all.impostors());
    REQUIRE(all.impostors()->bakedImpostors() == 2);
    const std::uint64_t one = all.impostors()->impostorOfId(0)->bytes().total();
    CHECK(all.selection().impostorObjects == 2);

    // A cap of one and a half impostors: one is kept, and it is the sphere's (more saved per byte).
    o.impostorMemoryBytes = one + one / 2;
    LodController capped(*fx.gpu, o);
    capped.select(far, {64, 48});
    REQUIRE(capped.impostors());
    CHECK(capped.impostors()->bakedImpostors() == 1);
    CHECK(capped.impostors()->bytes().total() <= o.impostorMemoryBytes);
    CHECK(capped.selection().impostorObjects == 1);
    CHECK(capped.impostors()->impostorOf(0) != nullptr);  // the sphere
    CHECK(capped.impostors()->impostorOf(1) == nullptr);  // the box draws geometry
    CHECK_FALSE(capped.selection().objects[1].impostor);

    // A cap of one impostor's images and rectangles: the bake fits the prediction (which cannot
    // know the vertex buffer), the baked impostor does not, and the selection evicts it.
    const ImpostorMemory m = all.impostors()->impostorOfId(0)->bytes();
    REQUIRE(m.vertexBuffer > 0);
    o.impostorMemoryBytes = m.images + m.rectangles;
    LodController tight(*fx.gpu, o);
    tight.select(far, {64, 48});
    REQUIRE(tight.impostors());
    CHECK(tight.impostors()->evictedImpostors() == 1);
    CHECK(tight.impostors()->bytes().total() == 0);
    CHECK(tight.selection().impostorObjects == 0);
    CHECK(tight.impostors()->reasonOf(0).find("memory cap") != std::string::npos);
    // Evicted is not baked again, and the box, whose bake the controller now knows would not fit
    // (it learnt the vertex buffer's share), is not baked either: nothing is baked to be evicted.
    tight.select(far, {64, 48});
    CHECK(tight.impostors()->evictedImpostors() == 1);
    CHECK(tight.impostors()->bakedImpostors() == 0);
    CHECK_FALSE(tight.impostors()->tried(1));
}

TEST_CASE("bake budget: one bake per frame under a tiny budget, geometry until an impostor is ready") {
    Scene s;
    s.name = "two-meshes";
    s.materials = {Material{}};
    for (float x : {-1.5f, 1.5f}) {
        Node node;
        node.local = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f));
        node.meshes = {s.addMesh(x < 0.0f ? makeSphere(1.0f, 48, 24) : makeBox(glm::vec3(-1.0f), glm::vec3(1.0f)))};
        s.addNode(node);
    }
    test::Fixture fx(std::move(s));
    Camera far = fx.camera;
    far.position = glm::vec3(0.0f, 0.0f, 40.0f);
    far.fitClipPlanes(fx.gpu->bounds());
    LodOptions o = cachedImpostors(LodMode::Impostors, {});
    o.bakeBudgetMs = 1e-6;
    LodController lod(*fx.gpu, o);
    lod.select(far, {64, 48});
    REQUIRE(lod.impostors());
    CHECK(lod.impostors()->bakedImpostors() == 1);
    CHECK(lod.impostors()->pendingBakes() == 1);
    CHECK(lod.selection().impostorObjects == 1);  // the other draws its geometry meanwhile
    lod.select(far, {64, 48});
    CHECK(lod.impostors()->bakedImpostors() == 2);
    CHECK(lod.impostors()->pendingBakes() == 0);
    CHECK(lod.selection().impostorObjects == 2);
    // Without a budget both bake in the first frame.
    o.bakeBudgetMs = 0.0;
    LodController all(*fx.gpu, o);
    all.select(far, {64, 48});
    CHECK(all.impostors()->bakedImpostors() == 2);
    CHECK(all.impostors()->pendingBakes() == 0);
}

TEST_CASE("cost model cache: auto keeps its calibration for the next run on this device, and only that") {
    test::Fixture fx(makeFieldScene(4, false));
    TempFolder folder("cost-model-cache");
    const fs::path file = folder.path / kCostModelFile;
    LodOptions auto_ = cachedImpostors(LodMode::Auto, folder.path);
    LodCostModel measured;
    {
        LodController first(*fx.gpu, auto_);
        first.select(fx.camera, {64, 48});
        REQUIRE(first.calibration());
        CHECK_FALSE(first.calibration()->kept);
        CHECK(first.calibration()->wallMs > 0.0);
        measured = first.calibration()->model;
        CHECK(fs::exists(file));
    }
    // A second run on the same device reads it: every coefficient as measured, nothing timed.
    {
        LodController second(*fx.gpu, auto_);
        second.select(fx.camera, {64, 48});
        REQUIRE(second.calibration());
        CHECK(second.calibration()->kept);
        CHECK(second.calibration()->wallMs == 0.0);
        const LodCostModel& m = second.calibration()->model;
        CHECK(m.geometryMsPerMegatriangle == measured.geometryMsPerMegatriangle);
        CHECK(m.impostorMsPerKiloquad == measured.impostorMsPerKiloquad);
        CHECK(m.impostorMsPerKilosidePx == measured.impostorMsPerKilosidePx);
        CHECK(m.impostorFixedMs == measured.impostorFixedMs);
    }
    // Another device's, another version's, or a damaged file is not used, and the calibration
    // made instead replaces it.
    const std::string key = currentDeviceKey();
    REQUIRE(loadCostModel(file, key));
    CHECK_FALSE(loadCostModel(file, key + " (another)"));
    for (const char* text : {"{\"version\": 1, \"device\": \"@\", \"model\": {}}", "not json", "{\"version\": 2}",
                             "{\"version\": 2, \"device\": \"@\", \"model\": {\"geometry_fixed_ms\": -1}}"}) {
        CAPTURE(text);
        std::string content = text;
        if (const auto at = content.find('@'); at != std::string::npos) content.replace(at, 1, key);
        std::ofstream(file) << content;
        CHECK_FALSE(loadCostModel(file, key));
        LodController again(*fx.gpu, auto_);
        again.select(fx.camera, {64, 48});
        REQUIRE(again.calibration());
        CHECK_FALSE(again.calibration()->kept);
        CHECK(loadCostModel(file, key));  // replaced by the new calibration
    }
    // Without a cache folder nothing is kept or read.
    LodController uncached(*fx.gpu, cachedImpostors(LodMode::Auto, {}));
    uncached.select(fx.camera, {64, 48});
    REQUIRE(uncached.calibration());
    CHECK_FALSE(uncached.calibration()->kept);
}

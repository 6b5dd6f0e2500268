// Which shipped models bound a volume (closed and consistently oriented after welding), so the
// volumetric techniques render them as media. Skips where ../shared/scenes-data is absent.
#include "test_paths.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/mesh_volume.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

using namespace strata;

TEST_CASE("shipped models: closed volumes or not, as measured") {
    const std::filesystem::path dir = test::sharedScenesDir();
    if (!std::filesystem::is_directory(dir)) {
        MESSAGE("skipped: " << dir.string() << " is absent");
        return;
    }
    // Measured once and stated: cow, fandisk and spot are watertight; the bunny (the scan's
    // holes at its base), suzanne (open eyes) and the teapot (lid and spout seams) are not, and
    // are drawn as surfaces by the volumetric techniques.
    struct Expected {
        const char* name;
        bool closed;
        std::size_t openEdges;
    };
    for (const Expected& e : {Expected{"cow", true, 0}, Expected{"fandisk", true, 0}, Expected{"spot", true, 0},
                              Expected{"stanford-bunny", false, 223}, Expected{"suzanne", false, 42},
                              Expected{"teapot", false, 160}}) {
        CAPTURE(e.name);
        const Scene s = loadGltf(dir / (std::string(e.name) + ".glb"));
        REQUIRE(s.meshes.size() == 1);
        const MeshVolume v = analyzeMeshVolume(s.meshes[0]);
        CHECK(v.closed == e.closed);
        CHECK(v.openEdges == e.openEdges);
        CHECK(v.frontFacesOutward);
        CHECK(v.signedVolume > 0.0);
    }
}

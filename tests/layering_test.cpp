// The core's folders depend one way: gl <- scene, camera, image <- render <- oit <- frame <- bench.
// A folder that includes a header from one above it makes a cycle; this test names the line.
#include "test_paths.hpp"
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace fs = std::filesystem;

TEST_CASE("core folders include only folders below them") {
    // Each folder with the folders it must not include.
    const std::map<std::string, std::set<std::string>> forbidden = {
        {"gl", {"render", "oit", "frame", "bench", "scene"}},
        {"render", {"oit", "frame", "bench"}},
        {"oit", {"frame", "bench"}},
        {"frame", {"bench"}},
    };
    const fs::path core = strata::test::sourceDir() / "core";
    REQUIRE(fs::is_directory(core));
    int files = 0;
    for (const auto& [folder, above] : forbidden) {
        for (const auto& entry : fs::recursive_directory_iterator(core / folder)) {
            if (!entry.is_regular_file()) continue;
            ++files;
            std::ifstream in(entry.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n) {
                if (line.rfind("#include \"", 0) != 0) continue;
                std::string target = line.substr(10, line.find('/', 10) - 10);
                CAPTURE(entry.path().string() + ":" + std::to_string(n) + ": " + line);
                CHECK(above.count(target) == 0);
            }
        }
    }
    CHECK(files > 20);
}

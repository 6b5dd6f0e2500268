// readBoundedFile and every reader built on it: a special file or one over its format's limit is
// refused before it is read, with one line naming the file, the limit and the size.
#include "camera/camera_path.hpp"
#include "gltf_test_builder.hpp"
#include "io/bounded_read.hpp"
#include "oit/technique_settings.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/scene_description.hpp"
#include "tracking/trace_io.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <functional>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace strata;
using strata::test::tempDir;
using strata::test::writeFile;

namespace {

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

// A file that claims `bytes` without using the disk (a hole), as `truncate -s` makes.
fs::path sparseFile(const std::string& name, std::uintmax_t bytes) {
    fs::path p = tempDir() / name;
    writeFile(p, "");
    fs::resize_file(p, bytes);
    return p;
}

fs::path fifo(const std::string& name) {
    fs::path p = tempDir() / name;
    fs::remove(p);
    REQUIRE(::mkfifo(p.c_str(), 0600) == 0);
    return p;
}

}  // namespace

TEST_CASE("readBoundedFile: regular files within the limit are read whole") {
    auto p = tempDir() / "bounded-ok.txt";
    writeFile(p, std::string("abc\0def", 7));
    CHECK(readBoundedFile(p, {7, "a test file"}) == std::string("abc\0def", 7));
    CHECK(readBoundedFile(p, {7, "a test file"}).size() == 7);  // exactly at the limit is allowed
    writeFile(p, "");
    CHECK(readBoundedFile(p, {7, "a test file"}).empty());
}

TEST_CASE("readBoundedFile: devices, FIFOs, folders, missing and oversized files are named and refused") {
    const InputLimit limit{1 << 20, "a test file"};
    CHECK(errorOf([&] { readBoundedFile("/dev/zero", limit); }) == "/dev/zero: is a character device, not a regular file");
    // A FIFO without a writer would block a plain open(); it is refused before opening.
    auto f = fifo("bounded.fifo");
    CHECK(errorOf([&] { readBoundedFile(f, limit); }) == f.string() + ": is a FIFO, not a regular file");
    CHECK(errorOf([&] { readBoundedFile(tempDir(), limit); }) == tempDir().string() + ": is a folder, not a regular file");
    CHECK(errorOf([&] { readBoundedFile(tempDir() / "absent", limit); }) == (tempDir() / "absent").string() + ": no such file");
    // 2 GiB of hole: refused from its size, without reading (or allocating) a byte of it.
    auto big = sparseFile("bounded-sparse.bin", std::uintmax_t(2) << 30);
    CHECK(errorOf([&] { readBoundedFile(big, limit); }) ==
          big.string() + ": 2 GiB (2147483648 bytes) is over the 1 MiB limit for a test file");
    auto over = sparseFile("bounded-over.bin", (1 << 20) + 1);
    CHECK(errorOf([&] { readBoundedFile(over, limit); }) ==
          over.string() + ": 1.0 MiB (1048577 bytes) is over the 1 MiB limit for a test file");
    if (::geteuid() != 0) {  // root reads anything
        auto locked = tempDir() / "bounded-locked.txt";
        writeFile(locked, "x");
        fs::permissions(locked, fs::perms::none);
        CHECK(errorOf([&] { readBoundedFile(locked, limit); }) == locked.string() + ": cannot open: Permission denied");
    }
}

TEST_CASE("formatBytes: the sizes the messages and the README give") {
    CHECK(formatBytes(0) == "0 bytes");
    CHECK(formatBytes(1) == "1 byte");
    CHECK(formatBytes(1023) == "1023 bytes");
    CHECK(formatBytes(1024) == "1 KiB");
    CHECK(formatBytes(std::uintmax_t(3) << 29) == "1.5 GiB");
    CHECK(formatBytes(kGltfLimit.bytes) == "512 MiB");
    CHECK(formatBytes(kCameraPathLimit.bytes) == "64 MiB");
}

TEST_CASE("every reader: /dev/zero, a FIFO, a folder and a sparse file over its limit, each named") {
    struct Reader {
        const char* name;
        InputLimit limit;
        std::function<void(const fs::path&)> read;
    };
    const Reader readers[] = {
        {"glb", kGltfLimit, [](const fs::path& p) { loadGltf(p); }},
        {"json", kSceneDescriptionLimit, [](const fs::path& p) { loadSceneDescription(p); }},
        {"path", kCameraPathLimit, [](const fs::path& p) { CameraPath::read(p); }},
        {"trace", kTraceLimit, [](const fs::path& p) { tracking::readTrace(p.string()); }},
        {"csv", kTraceLimit, [](const fs::path& p) { tracking::readTrace(p.string()); }},
        {"preset", kSettingsPresetLimit, [](const fs::path& p) { readSettingsPreset(p.string()); }},
    };
    for (const Reader& r : readers) {
        CAPTURE(r.name);
        CHECK(errorOf([&] { r.read("/dev/zero"); }) == "/dev/zero: is a character device, not a regular file");
        auto f = fifo(std::string("reader.") + r.name);
        CHECK(errorOf([&] { r.read(f); }) == f.string() + ": is a FIFO, not a regular file");
        fs::path folder = tempDir() / (std::string("folder.") + r.name);
        fs::create_directories(folder);
        CHECK(errorOf([&] { r.read(folder); }) == folder.string() + ": is a folder, not a regular file");
        auto big = sparseFile(std::string("sparse.") + r.name, r.limit.bytes + 1);
        CHECK(errorOf([&] { r.read(big); }) == big.string() + ": " + formatBytes(r.limit.bytes + 1) + " (" +
                                                   std::to_string(r.limit.bytes + 1) + " bytes) is over the " +
                                                   formatBytes(r.limit.bytes) + " limit for " + r.limit.format);
        fs::remove(big);
        fs::remove(f);
    }
}

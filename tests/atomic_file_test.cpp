// writeFileAtomically: the destination is complete or untouched, never half-written, and no
// temporary is left behind whichever way the write fails.
#include "io/atomic_file.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace strata;

namespace {

struct TempDir {
    fs::path dir;
    TempDir() {
        dir = fs::temp_directory_path() / ("strata-atomic-" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(dir, ec);
    }
};

std::set<std::string> listing(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(fs::relative(e.path(), dir).string());
    return names;
}

std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string errorOf(const std::function<void()>& write) {
    try {
        write();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("atomic file: writes the whole text and leaves only the destination") {
    TempDir tmp;
    fs::path file = tmp.dir / "report.json";
    writeTextFile(file, "{\"a\": 1}\n");
    CHECK(contents(file) == "{\"a\": 1}\n");
    writeTextFile(file, "replaced");
    CHECK(contents(file) == "replaced");
    CHECK(listing(tmp.dir) == std::set<std::string>{"report.json"});
    // Writers that choose the format by the extension (OpenImageIO) see the destination's.
    writeFileAtomically(tmp.dir / "image.exr", [&](const fs::path& temporary) {
        CHECK(temporary.extension() == ".exr");
        CHECK(temporary.parent_path() == tmp.dir);
        CHECK(fs::exists(temporary));
        std::ofstream(temporary) << "x";
    });
    CHECK(listing(tmp.dir) == std::set<std::string>{"report.json", "image.exr"});
}

TEST_CASE("atomic file: a failing writer leaves the old file and no temporary") {
    TempDir tmp;
    fs::path file = tmp.dir / "bench.csv";
    writeTextFile(file, "old");
    fs::path seen;
    std::string error = errorOf([&] {
        writeFileAtomically(file, [&](const fs::path& temporary) {
            seen = temporary;
            std::ofstream(temporary) << "half of the new conte";
            throw std::runtime_error("disk on fire");
        });
    });
    CHECK(error == file.string() + ": disk on fire");
    CHECK(seen.parent_path() == tmp.dir);  // the temporary was in the destination's folder...
    CHECK_FALSE(fs::exists(seen));         // ...and is gone
    CHECK(contents(file) == "old");
    CHECK(listing(tmp.dir) == std::set<std::string>{"bench.csv"});
}

TEST_CASE("atomic file: destinations that cannot be written are refused, naming the file, leaving nothing") {
    TempDir tmp;
    fs::create_directories(tmp.dir / "folder");
    ::mkfifo((tmp.dir / "fifo").c_str(), 0600);
    const std::set<std::string> before = listing(tmp.dir);
    struct Case {
        fs::path path;
        std::string message;
    };
    const Case cases[] = {
        {tmp.dir / "folder", ": is a folder"},
        {tmp.dir / "missing" / "out.png", ": folder " + (tmp.dir / "missing").string() + " does not exist"},
        {tmp.dir / "fifo" / "out.png", ": " + (tmp.dir / "fifo").string() + " is not a folder"},
        {tmp.dir / "fifo", ": exists and is not a regular file"},
        {tmp.dir / "folder" / "", ": names a folder, not a file"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.path);
        CHECK(errorOf([&] { checkWritable(c.path); }) == c.path.string() + c.message);
        CHECK(errorOf([&] { writeTextFile(c.path, "text"); }) == c.path.string() + c.message);
        CHECK(listing(tmp.dir) == before);
    }
    // A folder without write permission (root writes anyway, so only checked for other users).
    if (::geteuid() != 0) {
        fs::create_directories(tmp.dir / "locked");
        fs::permissions(tmp.dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
        fs::path file = tmp.dir / "locked" / "out.txt";
        CHECK(errorOf([&] { writeTextFile(file, "text"); }).rfind(file.string() + ": cannot write", 0) == 0);
        CHECK(errorOf([&] { checkWritable(file); }).rfind(file.string() + ": cannot write in", 0) == 0);
        CHECK(fs::is_empty(tmp.dir / "locked"));
    }
}

TEST_CASE("output batch: every output appears at commit, none before") {
    TempDir tmp;
    OutputBatch batch;
    batch.createFolder(tmp.dir / "report" / "images");
    batch.addText(tmp.dir / "report" / "images" / "a.png", "image");
    batch.addText(tmp.dir / "report" / "bench.json", "{}");
    // Written to temporaries already, under no final name yet.
    CHECK_FALSE(fs::exists(tmp.dir / "report" / "bench.json"));
    CHECK_FALSE(fs::exists(tmp.dir / "report" / "images" / "a.png"));
    batch.commit();
    CHECK(listing(tmp.dir) == std::set<std::string>{"report", "report/images", "report/images/a.png", "report/bench.json"});
    CHECK(contents(tmp.dir / "report" / "bench.json") == "{}");
}

TEST_CASE("output batch: a failure on the way leaves no output, no temporary and no folder it made") {
    TempDir tmp;
    fs::create_directories(tmp.dir / "kept");
    writeTextFile(tmp.dir / "image.png", "old image");
    std::string error = errorOf([&] {
        OutputBatch batch;
        batch.createFolder(tmp.dir / "kept" / "new" / "deeper");
        batch.addText(tmp.dir / "kept" / "new" / "deeper" / "x.png", "x");
        batch.addText(tmp.dir / "image.png", "new image");  // the main image: written, not committed
        // The secondary output fails (a heatmap that cannot be written): the batch is dropped.
        batch.add(tmp.dir / "heat.exr", [](const fs::path&) { throw std::runtime_error("cannot write image: full"); });
        batch.commit();
    });
    CHECK(error == (tmp.dir / "heat.exr").string() + ": cannot write image: full");
    // The folder that existed stays; the ones the batch made are gone; the old image is untouched.
    CHECK(listing(tmp.dir) == std::set<std::string>{"kept", "image.png"});
    CHECK(contents(tmp.dir / "image.png") == "old image");
}

TEST_CASE("output batch: folders that cannot be made are refused before anything is made") {
    TempDir tmp;
    writeTextFile(tmp.dir / "file", "x");
    CHECK(errorOf([&] { checkFolderCreatable(tmp.dir / "file"); }) == (tmp.dir / "file").string() + ": is not a folder");
    CHECK(errorOf([&] { checkFolderCreatable(tmp.dir / "file" / "images"); }) ==
          (tmp.dir / "file" / "images").string() + ": " + (tmp.dir / "file").string() + " is not a folder");
    CHECK_NOTHROW(checkFolderCreatable(tmp.dir / "new" / "images"));
    CHECK_NOTHROW(checkFolderCreatable(tmp.dir));
    CHECK(listing(tmp.dir) == std::set<std::string>{"file"});
    OutputBatch batch;
    CHECK(errorOf([&] { batch.createFolder(tmp.dir / "file" / "images"); }).find("file/images: ") != std::string::npos);
}

TEST_CASE("output batch: a rename that fails at commit names its output and leaves the outputs as they were") {
    TempDir tmp;
    writeTextFile(tmp.dir / "a.json", "old a");
    writeTextFile(tmp.dir / "d.json", "old d");
    std::string error = errorOf([&] {
        OutputBatch batch;
        batch.addText(tmp.dir / "a.json", "a");    // replaces a file
        batch.addText(tmp.dir / "new.json", "n");  // creates one
        batch.addText(tmp.dir / "b.json", "b");
        batch.addText(tmp.dir / "d.json", "d");
        fs::create_directories(tmp.dir / "b.json" / "inside");  // put in b's place after the checks
        batch.commit();
    });
    CHECK(error.rfind((tmp.dir / "b.json").string() + ": ", 0) == 0);
    // a and new were renamed before the failure: a is the old a again, new is gone; d was never
    // touched; no temporary or kept copy is left.
    CHECK(listing(tmp.dir) == std::set<std::string>{"a.json", "b.json", "b.json/inside", "d.json"});
    CHECK(contents(tmp.dir / "a.json") == "old a");
    CHECK(contents(tmp.dir / "d.json") == "old d");
}

TEST_CASE("output batch: a commit that succeeds replaces the old files and keeps no copy") {
    TempDir tmp;
    writeTextFile(tmp.dir / "a.json", "old a");
    OutputBatch batch;
    batch.addText(tmp.dir / "a.json", "a");
    batch.addText(tmp.dir / "b.json", "b");
    batch.commit();
    CHECK(listing(tmp.dir) == std::set<std::string>{"a.json", "b.json"});
    CHECK(contents(tmp.dir / "a.json") == "a");
}

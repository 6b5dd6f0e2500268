#include "io/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace strata {
namespace fs = std::filesystem;

namespace {

std::runtime_error failure(const fs::path& path, const std::string& what) {
    return std::runtime_error(path.string() + ": " + what);
}

std::string errnoText(int error) { return std::generic_category().message(error); }

fs::path folderOf(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

// The checks that need no write: the folder is there and is a folder, and `path` is not
// something a rename would replace wrongly (a folder, or a device such as /dev/null).
void checkPlace(const fs::path& path) {
    if (path.filename().empty()) throw failure(path, "names a folder, not a file");
    std::error_code ec;
    const fs::path folder = folderOf(path);
    auto folderStatus = fs::status(folder, ec);
    if (!fs::exists(folderStatus)) throw failure(path, "folder " + folder.string() + " does not exist");
    if (!fs::is_directory(folderStatus)) throw failure(path, folder.string() + " is not a folder");
    auto status = fs::status(path, ec);
    if (fs::is_directory(status)) throw failure(path, "is a folder");
    if (fs::exists(status) && !fs::is_regular_file(status)) throw failure(path, "exists and is not a regular file");
}

// A name no other writer (thread or process) uses: the destination's name, a marker, this
// process and a counter, and the destination's extension last.
fs::path temporaryName(const fs::path& path) {
    static std::atomic<unsigned> counter{0};
    std::string name = path.filename().string() + ".partial-" + std::to_string(::getpid()) + "-" +
                       std::to_string(counter++) + path.extension().string();
    return folderOf(path) / name;
}

// Flushes the finished temporary to disk before the rename, so a crash or power cut after the
// rename cannot leave the destination's name on an empty or partial file.
void syncToDisk(const fs::path& file) {
    int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error("cannot reopen the written file: " + errnoText(errno));
    int rc = ::fsync(fd);
    int error = errno;
    ::close(fd);
    if (rc != 0) throw std::runtime_error("cannot flush to disk: " + errnoText(error));
}

void writeBytes(const fs::path& file, std::string_view text) {
    std::FILE* f = std::fopen(file.c_str(), "wb");
    if (!f) throw std::runtime_error("cannot write: " + errnoText(errno));
    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    int error = errno;
    if (std::fclose(f) != 0 && ok) {
        ok = false;
        error = errno;
    }
    if (!ok) throw std::runtime_error("write failed: " + errnoText(error));
}

}  // namespace

void checkWritable(const fs::path& path) {
    checkPlace(path);
    const fs::path folder = folderOf(path);
    if (::access(folder.c_str(), W_OK) != 0) throw failure(path, "cannot write in " + folder.string() + ": " + errnoText(errno));
}

void checkFolderCreatable(const fs::path& folder) {
    std::error_code ec;
    fs::path existing = folder;
    while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path())
        existing = existing.parent_path();
    if (existing.empty()) existing = ".";
    if (!fs::is_directory(existing, ec))
        throw failure(folder, existing == folder ? std::string("is not a folder") : existing.string() + " is not a folder");
    // The folder itself when it exists (outputs go into it), else the part that exists.
    if (::access(existing.c_str(), W_OK) != 0)
        throw failure(folder, "cannot write in " + existing.string() + ": " + errnoText(errno));
}

namespace {

// Writes `path`'s content to a fresh temporary beside it and flushes it; returns the temporary.
// On failure the temporary is removed and "<path>: <what>" thrown.
fs::path stage(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
    checkPlace(path);
    const fs::path temporary = temporaryName(path);
    // O_EXCL: the name is ours alone; an existing file of that name is never overwritten.
    int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw failure(path, "cannot write: " + errnoText(errno));
    ::close(fd);
    auto removeTemporary = [&] {
        std::error_code ignored;
        fs::remove(temporary, ignored);
    };
    try {
        write(temporary);
        syncToDisk(temporary);
    } catch (const std::exception& e) {
        removeTemporary();
        throw failure(path, e.what());
    } catch (...) {
        removeTemporary();
        throw;
    }
    return temporary;
}

}  // namespace

OutputBatch::~OutputBatch() {
    if (committed_) return;
    std::error_code ignored;
    for (const Staged& s : staged_) fs::remove(s.temporary, ignored);
    // Deepest first; fs::remove leaves a folder that holds anything it did not create.
    for (auto f = createdFolders_.rbegin(); f != createdFolders_.rend(); ++f) fs::remove(*f, ignored);
}

void OutputBatch::createFolder(const fs::path& folder) {
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = folder; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    for (auto p = missing.rbegin(); p != missing.rend(); ++p) {
        if (!fs::create_directory(*p, ec) && ec) throw failure(*p, "cannot create folder: " + ec.message());
        createdFolders_.push_back(*p);
    }
    if (!fs::is_directory(folder, ec)) throw failure(folder, "is not a folder");
}

void OutputBatch::add(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
    if (committed_) throw std::logic_error("OutputBatch::add after commit");
    staged_.push_back({path, stage(path, write)});
}

void OutputBatch::addText(const fs::path& path, std::string_view text) {
    add(path, [&](const fs::path& temporary) { writeBytes(temporary, text); });
}

void OutputBatch::commit() {
    // The batch lands whole or not at all: before each rename the file it replaces is kept
    // under a second name (a hard link, else a copy; the destination itself stays in place, so
    // each rename still replaces it atomically), and a rename that fails puts back what the
    // earlier ones replaced and removes what they created.
    struct Replaced {
        fs::path path, kept;   // kept: the old file's second name, empty when none was made
        bool existed = false;  // something was at `path` before
    };
    std::vector<Replaced> done;
    auto undo = [&] {
        std::error_code ignored;
        for (auto r = done.rbegin(); r != done.rend(); ++r) {
            if (!r->kept.empty()) ::rename(r->kept.c_str(), r->path.c_str());
            else if (!r->existed) fs::remove(r->path, ignored);
            // An old file that could not be kept stays replaced: removing the new one too would
            // leave neither.
        }
    };
    for (std::size_t i = 0; i < staged_.size(); ++i) {
        const fs::path& path = staged_[i].path;
        Replaced r{path, {}, false};
        std::error_code ec;
        const fs::file_status old = fs::symlink_status(path, ec);
        r.existed = fs::exists(old);
        if (fs::is_symlink(old) || fs::is_regular_file(old)) {
            r.kept = temporaryName(path);
            if (fs::is_symlink(old)) fs::copy_symlink(path, r.kept, ec);
            else {
                fs::create_hard_link(path, r.kept, ec);
                if (ec) fs::copy_file(path, r.kept, ec);
            }
            if (ec) r.kept.clear();  // cannot keep it: this one cannot be put back
        }
        if (::rename(staged_[i].temporary.c_str(), path.c_str()) != 0) {
            const int error = errno;
            std::error_code ignored;
            if (!r.kept.empty()) fs::remove(r.kept, ignored);  // the destination was not touched
            undo();
            // The destructor removes the temporaries not renamed (those renamed are gone).
            // A folder or file put in the destination's place since checkPlace.
            throw failure(path, error == EISDIR ? std::string("is a folder") : "cannot move into place: " + errnoText(error));
        }
        done.push_back(std::move(r));
    }
    std::error_code ignored;
    for (const Replaced& r : done)
        if (!r.kept.empty()) fs::remove(r.kept, ignored);
    committed_ = true;
}

void writeFileAtomically(const fs::path& path, const std::function<void(const fs::path& temporary)>& write) {
    OutputBatch batch;
    batch.add(path, write);
    batch.commit();
}

void writeTextFile(const fs::path& path, std::string_view text) {
    writeFileAtomically(path, [&](const fs::path& temporary) { writeBytes(temporary, text); });
}

}  // namespace strata

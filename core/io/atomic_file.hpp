#pragma once
// Every file Strata writes (images, bench JSON and CSV, the demo report, camera paths, head-pose
// traces, screenshots) goes through here, so DESIGN.md's "nothing half-written" holds in one
// place. The bytes go to a temporary file in the destination's own folder (a rename within one
// file system is atomic), which is renamed over the destination only once it is complete and
// flushed to disk. On any failure the temporary is removed and std::runtime_error
// "<path>: <what is wrong>" is thrown; the destination keeps what it held before, or stays absent.
#include <filesystem>
#include <functional>
#include <string_view>
#include <vector>

namespace strata {

// Several outputs of one command that appear together or not at all (an image and its
// heatmap, a bench's JSON, CSV and images, the demo's report folder). Each add() writes its
// file under a temporary name in the destination's folder at once, as the command goes, so
// nothing is held in memory; commit() renames them all into place once everything succeeded.
// Destroyed without commit() (an exception on the way), the batch removes every temporary and
// every folder it created, leaving the disk as the command found it. Should a rename fail half
// way through commit() (the disk changed under the command), the outputs already renamed stay
// and the rest are removed; the error names the one that failed.
class OutputBatch {
public:
    OutputBatch() = default;
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;

    // Creates `folder` and its missing parents now (outputs are added into it); those that did
    // not exist are removed again unless commit() is reached. Throws "<folder>: <what>".
    void createFolder(const std::filesystem::path& folder);
    // Writes `path`'s content to its temporary through `write`, as writeFileAtomically does.
    void add(const std::filesystem::path& path,
             const std::function<void(const std::filesystem::path& temporary)>& write);
    void addText(const std::filesystem::path& path, std::string_view text);
    // Renames every added output into place, in the order added.
    void commit();

private:
    struct Staged {
        std::filesystem::path path, temporary;
    };
    std::vector<Staged> staged_;
    std::vector<std::filesystem::path> createdFolders_;  // parents first
    bool committed_ = false;
};

// `write` fills the file at the temporary path it is given (the file exists, empty; the name
// ends in the destination's extension, for writers such as OpenImageIO that choose the format by
// it). It fails by throwing; its message is appended to "<path>: ".
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& temporary)>& write);

// `text` (any bytes) to `path`, the same way.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

// Throws the error a write to `path` would meet before any byte is written: its folder is
// missing or not a folder, `path` is a folder or another non-regular file, or the folder is
// not writable. Commands call it for every output before the work that produces the output,
// so a typo costs nothing; the write itself still checks everything.
void checkWritable(const std::filesystem::path& path);

// Throws what OutputBatch::createFolder(folder) would meet, creating nothing: `folder` exists
// and is not a folder, or the nearest part of it that exists is not a writable folder.
void checkFolderCreatable(const std::filesystem::path& folder);

}  // namespace strata

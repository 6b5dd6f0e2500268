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

namespace strata {

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

}  // namespace strata

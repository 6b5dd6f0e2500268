#pragma once
// The one way Strata reads an input file: check what the path is, check its size against a
// limit for its format, then read it in pieces, never past the limit. A model, a scene, a path
// or a trace that is /dev/zero, a FIFO, a folder or a 2 GB sparse file is refused at once with a
// message naming the file, the limit and the size, instead of being read whole until memory
// runs out. The limits are stated in docs/command-line.md ("Input limits"); keep the two in step.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace strata {

// A file a reader refused or could not read; what() is one line "<file>: <what is wrong>".
// Loaders rethrow it as their own error type (LoadError, TraceError) with the same message.
class ReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct InputLimit {
    std::uintmax_t bytes;
    const char* format;  // names the format in messages: "larger than the 1 MiB limit for <format>"
};

// Per format. A scene may be large (a scanned model), so glTF gets the most; the text formats
// are a few kilobytes in practice and get a limit far above any real file.
inline constexpr InputLimit kGltfLimit{std::uintmax_t(512) << 20, "a glTF file or buffer"};
inline constexpr InputLimit kSceneDescriptionLimit{std::uintmax_t(1) << 20, "a scene description"};
inline constexpr InputLimit kSettingsPresetLimit{std::uintmax_t(1) << 20, "a settings preset"};
inline constexpr InputLimit kCameraPathLimit{std::uintmax_t(64) << 20, "a camera path"};
inline constexpr InputLimit kTraceLimit{std::uintmax_t(64) << 20, "a head-pose trace"};

// The whole file at `path`. Throws ReadError when it does not exist, is not a regular file
// (a folder, FIFO, socket or device: checked before opening, so a FIFO cannot block), cannot be
// opened or read, or holds more than `limit.bytes` (checked against its size first, then while
// reading, so a file that grows or lies about its size is stopped at the limit too).
std::string readBoundedFile(const std::filesystem::path& path, const InputLimit& limit);

// "512 MiB", "1.5 GiB", "300 bytes": a size as the messages and the docs write it.
std::string formatBytes(std::uintmax_t bytes);

}  // namespace strata

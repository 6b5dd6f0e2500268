#include "io/bounded_read.hpp"

#include "io/printable.hpp"

#include <cerrno>
#include <cstdio>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace strata {
namespace {

ReadError failure(const std::filesystem::path& path, const std::string& what) {
    return ReadError(printable(path.string(), 120) + ": " + what);
}

std::string errnoText(int error) { return std::generic_category().message(error); }

const char* kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    return "not a regular file";
}

// The size both readable and exact: "1.0 MiB" alone would not say why 1 MiB + 1 byte is too much.
std::string tooLarge(std::uintmax_t size, const InputLimit& limit) {
    std::string exact = size < 1024 ? "" : " (" + std::to_string(size) + " bytes)";
    return formatBytes(size) + exact + " is over the " + formatBytes(limit.bytes) + " limit for " + limit.format;
}

// Closes the descriptor on every path out.
struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

std::string formatBytes(std::uintmax_t bytes) {
    const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
    if (bytes < 1024) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
    double v = double(bytes);
    int u = -1;
    while (v >= 1024.0 && u < 3) {
        v /= 1024.0;
        ++u;
    }
    char text[32];
    // Whole numbers as such ("64 MiB"), others to one decimal ("1.5 GiB").
    if (v == double(static_cast<std::uintmax_t>(v))) std::snprintf(text, sizeof text, "%.0f %s", v, units[u]);
    else std::snprintf(text, sizeof text, "%.1f %s", v, units[u]);
    return text;
}

std::string readBoundedFile(const std::filesystem::path& path, const InputLimit& limit) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        int error = errno;
        throw failure(path, error == ENOENT ? std::string("no such file") : "cannot open: " + errnoText(error));
    }
    if (!S_ISREG(st.st_mode)) throw failure(path, std::string("is ") + kindOf(st.st_mode) + ", not a regular file");
    if (std::uintmax_t(st.st_size) > limit.bytes) throw failure(path, tooLarge(std::uintmax_t(st.st_size), limit));
    // O_NONBLOCK: should the path have become a FIFO since stat, open must not wait for a writer.
    Fd f{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)};
    if (f.fd < 0) throw failure(path, "cannot open: " + errnoText(errno));
    if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode)) throw failure(path, "is not a regular file");
    std::string out;
    out.reserve(std::size_t(st.st_size));
    char chunk[1 << 16];
    for (;;) {
        ssize_t n = ::read(f.fd, chunk, sizeof chunk);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw failure(path, "read error: " + errnoText(errno));
        }
        if (n == 0) break;
        if (out.size() + std::size_t(n) > limit.bytes)
            throw failure(path, "grew past the " + formatBytes(limit.bytes) + " limit for " + limit.format + " while read");
        out.append(chunk, std::size_t(n));
    }
    return out;
}

}  // namespace strata

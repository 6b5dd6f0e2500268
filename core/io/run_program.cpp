#include "io/run_program.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace strata {
namespace {

// A pipe's two ends, closed when it goes out of scope (an exception on the way included).
struct Pipe {
    int fd[2] = {-1, -1};
    Pipe() {
        if (pipe2(fd, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    }
    ~Pipe() { closeEnd(0), closeEnd(1); }
    void closeEnd(int i) {
        if (fd[i] >= 0) ::close(fd[i]);
        fd[i] = -1;
    }
};

}  // namespace

bool programOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    if (!path || name.empty() || name.find('/') != std::string::npos) return false;
    std::string folders = path;
    for (std::size_t start = 0; start <= folders.size();) {
        std::size_t end = folders.find(':', start);
        if (end == std::string::npos) end = folders.size();
        const std::filesystem::path candidate = std::filesystem::path(folders.substr(start, end - start)) / name;
        if (end > start && ::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return true;
        start = end + 1;
    }
    return false;
}

ProgramResult runProgram(const std::vector<std::string>& arguments, std::string_view input) {
    if (arguments.empty()) throw std::invalid_argument("runProgram: no program named");
    const std::string& name = arguments.front();
    if (!programOnPath(name)) throw std::runtime_error(name + ": not found on PATH");
    Pipe in, out;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in.fd[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out.fd[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out.fd[1], STDERR_FILENO);
    std::vector<char*> argv;
    for (const auto& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, name.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw std::runtime_error(name + ": cannot start (" + std::strerror(spawned) + ")");
    in.closeEnd(0);
    out.closeEnd(1);
    // Our end of the input pipe never blocks: a write takes what fits and poll says when more does.
    fcntl(in.fd[1], F_SETFL, fcntl(in.fd[1], F_GETFL) | O_NONBLOCK);

    // Feed the input and read the output together, so neither side blocks on a full pipe.
    // A program that exits without reading its input must not kill us with SIGPIPE (restored
    // however this ends).
    struct IgnoreSigpipe {
        struct sigaction previous {};
        IgnoreSigpipe() {
            struct sigaction ignore {};
            ignore.sa_handler = SIG_IGN;
            sigaction(SIGPIPE, &ignore, &previous);
        }
        ~IgnoreSigpipe() { sigaction(SIGPIPE, &previous, nullptr); }
    } ignoreSigpipe;
    ProgramResult result;
    try {
        std::size_t written = 0;
        if (input.empty()) in.closeEnd(1);
        while (out.fd[0] >= 0) {
            pollfd fds[2] = {{out.fd[0], POLLIN, 0}, {in.fd[1], POLLOUT, 0}};
            const nfds_t count = in.fd[1] >= 0 ? 2 : 1;
            if (poll(fds, count, -1) < 0) {
                if (errno == EINTR) continue;
                break;
            }
            if (count == 2 && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP))) {
                const ssize_t n = ::write(in.fd[1], input.data() + written, input.size() - written);
                if (n > 0) written += std::size_t(n);
                if (n < 0 && errno != EINTR && errno != EAGAIN) written = input.size();  // the reader is gone
                if (written == input.size()) in.closeEnd(1);
            }
            if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
                char buffer[4096];
                const ssize_t n = ::read(out.fd[0], buffer, sizeof buffer);
                if (n > 0) result.output.append(buffer, std::size_t(n));
                else if (n == 0 || errno != EINTR) out.closeEnd(0);
            }
        }
    } catch (...) {
        // (An allocation failed.) The child is not left running or unreaped.
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
        throw;
    }
    // Both ends closed before waiting: a child still writing gets EPIPE, not a full pipe forever.
    in.closeEnd(1);
    out.closeEnd(0);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    return result;
}

}  // namespace strata

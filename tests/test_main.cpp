#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "gl/shader_program.hpp"

#include <cstdio>
#include <cstdlib>

// doctest's main, and with STRATA_GL_STATS set, how the run's GL programs were built (on a GPU
// driver, compilation can dominate a test run: docs/real-gpu-progress.md).
int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    const int result = context.run();
    if (std::getenv("STRATA_GL_STATS")) {
        const auto s = strata::gl::programBuildStats();
        std::printf("[strata] GL programs: %d compiled in %.2f s, %d loaded from binaries, %d binaries refused\n",
                    s.compiled, s.compileSeconds, s.loaded, s.rejected);
    }
    return result;
}

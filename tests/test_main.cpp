#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "gl/program_pool.hpp"
#include "gl/shader_program.hpp"

#include <cstdio>
#include <cstdlib>

namespace {

// With STRATA_GL_STATS set, how the run's GL programs were built so far, after every test case:
// on a GPU driver compilation can dominate a run, and a run cut short by a time limit still
// leaves its last line (docs/gpu-h100.md).
struct ProgramStatsListener : doctest::IReporter {
    explicit ProgramStatsListener(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {
        if (!std::getenv("STRATA_GL_STATS")) return;
        const auto s = strata::gl::programBuildStats();
        const auto pool = strata::gl::programPoolStats();
        std::printf("[strata] GL programs so far: %d compiled in %.2f s, %d loaded from binaries, %d binaries refused, "
                    "%zu recycled, %zu retired now\n",
                    s.compiled, s.compileSeconds, s.loaded, s.rejected, pool.recycled, pool.retired);
        std::fflush(stdout);
    }
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

}  // namespace

DOCTEST_REGISTER_LISTENER("strata-program-stats", 1, ProgramStatsListener);

int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    return context.run();
}

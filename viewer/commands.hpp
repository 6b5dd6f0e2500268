#pragma once
// The subcommands of `strata`, one file each. Each registers its options and a callback that
// throws on bad input; main() prints the one-line message and exits non-zero.
#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include <string>

namespace strata {

void registerModesCommand(CLI::App& app);
void registerRenderCommand(CLI::App& app);
void registerBenchCommand(CLI::App& app);
void registerAdviseCommand(CLI::App& app);
void registerViewCommand(CLI::App& app);
void registerDemoCommand(CLI::App& app);
#ifdef STRATA_HAVE_TRACKING
void registerTrackCommand(CLI::App& app);
#endif

// "WxH" -> size; throws std::invalid_argument naming the bad text.
glm::ivec2 parseSize(const std::string& text);

}  // namespace strata

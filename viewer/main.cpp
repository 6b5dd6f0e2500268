// strata: the command line. Errors are caught here, once, and printed as one line.
#include "commands.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    CLI::App app{"Strata: order-independent transparency and multi-fragment rendering, measured"};
    app.require_subcommand(1);
    strata::registerModesCommand(app);
    strata::registerRenderCommand(app);
    strata::registerBenchCommand(app);
    strata::registerViewCommand(app);
    strata::registerDemoCommand(app);
#ifdef STRATA_HAVE_TRACKING
    strata::registerTrackCommand(app);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "strata: %s\n", e.what());
        return 1;
    }
    return 0;
}

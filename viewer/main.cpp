// strata: the command line. Errors are caught here, once, and printed as one line.
#include "commands.hpp"

#include "io/heap_trim.hpp"
#include "io/interrupt.hpp"
#include "io/printable.hpp"

#include <cstdio>
#include <exception>
#include <string>

namespace {

// The last guard of the message contract (one line, printable, short), whatever a library or
// a path put in the text: line breaks become spaces, other control bytes and non-UTF-8 are
// escaped, and an overlong message keeps its head and tail. Loaders cut quoted input themselves.
std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return strata::printableMessage(text);
}

// "strata bench" when the rejection came while parsing a subcommand's arguments, else "strata".
std::string commandName(const CLI::App& app) {
    std::string name = "strata";
    for (const CLI::App* sub : app.get_subcommands()) name += " " + sub->get_name();
    return name;
}

// CLI11 calls `strata nosuch` "A subcommand is required"; say what is wrong instead.
std::string unknownCommand(const CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return {};
    std::string known;
    const auto all = app.get_subcommands([](const CLI::App*) { return true; });
    for (const CLI::App* sub : all) {
        if (sub->check_name(argv[1])) return {};
        known += (known.empty() ? "" : ", ") + sub->get_name();
    }
    return std::string("unknown command '") + argv[1] + "' (known: " + known + ")";
}

}  // namespace

int main(int argc, char** argv) {
    strata::keepFreedHeap();  // frame times free of page-fault churn (io/heap_trim.hpp)
    CLI::App app{"Strata: order-independent transparency and multi-fragment rendering, measured"};
    app.require_subcommand(1);
    strata::registerModesCommand(app);
    strata::registerRenderCommand(app);
    strata::registerBenchCommand(app);
    strata::registerAdviseCommand(app);
    strata::registerViewCommand(app);
    strata::registerDemoCommand(app);
#ifdef STRATA_HAVE_TRACKING
    strata::registerTrackCommand(app);
#endif
    strata::installInterruptHandlers();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help is a ParseError with status 0: CLI11 prints the help and that is success.
        if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
        // Every rejection of the command line (a value out of range, a missing or unknown option,
        // a value of the wrong type) is the same contract as any other bad input: one line on
        // stderr naming what is wrong, status 1. CLI11's own exit() would print two lines and
        // return its per-kind codes (105 for a range).
        if (std::string unknown = unknownCommand(app, argc, argv); !unknown.empty()) {
            std::fprintf(stderr, "strata: %s\n", oneLine(unknown).c_str());
            return 1;
        }
        std::string name = commandName(app);
        std::fprintf(stderr, "%s: %s (see %s --help)\n", name.c_str(), oneLine(e.what()).c_str(), name.c_str());
        return 1;
    } catch (const strata::Interrupted& e) {
        // Everything unwound on the way here: temporaries removed, completed outputs written.
        std::fprintf(stderr, "strata: %s\n", e.what());
        return e.exitStatus();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "strata: %s\n", oneLine(e.what()).c_str());
        return 1;
    }
    // A command that finished its work anyway (the viewer closes its window on the signal; a
    // signal after the bench's last check) still reports that it was stopped.
    if (const int signal = strata::interruptSignal()) {
        std::fprintf(stderr, "strata: %s\n", strata::Interrupted(signal).what());
        return 128 + signal;
    }
    return 0;
}

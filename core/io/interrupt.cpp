#include "io/interrupt.hpp"

#include <atomic>
#include <csignal>

#include <signal.h>

namespace strata {
namespace {

// Lock-free, so the handler may write it (async-signal-safe).
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void onInterrupt(int signal) {
    int none = 0;
    if (received.compare_exchange_strong(none, signal)) return;
    // A second request, of either kind (SA_RESETHAND resets only the one that came first): the
    // default action, now. signal() and raise() are async-signal-safe.
    ::signal(signal, SIG_DFL);
    ::raise(signal);
}

// The signals handled (not those ignored at startup), so clearInterrupt can re-arm them.
constexpr int kSignals[2] = {SIGINT, SIGTERM};
bool handled[2] = {false, false};

void arm(int signal) {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    // SA_RESETHAND: the first signal asks; a second one gets the default action and ends us.
    // SA_RESTART: a blocking call the signal interrupts resumes (the work polls the flag).
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    sigaction(signal, &action, nullptr);
}

std::string describe(int signal) {
    switch (signal) {
    case SIGINT: return "interrupted by SIGINT";
    case SIGTERM: return "interrupted by SIGTERM";
    default: return "interrupted by signal " + std::to_string(signal);
    }
}

}  // namespace

Interrupted::Interrupted(int signal) : std::runtime_error(describe(signal)), signal_(signal) {}

void installInterruptHandlers() {
    static const bool installed = [] {
        for (int i = 0; i < 2; ++i) {
            // A signal ignored when we start stays ignored (nohup, a shell's background job).
            struct sigaction previous {};
            if (sigaction(kSignals[i], nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
            arm(kSignals[i]);
            handled[i] = true;
        }
        return true;
    }();
    (void)installed;
}

int interruptSignal() { return received.load(); }

void throwIfInterrupted() {
    if (const int signal = received.load()) throw Interrupted(signal);
}

void clearInterrupt() {
    received.store(0);
    for (int i = 0; i < 2; ++i)
        if (handled[i]) arm(kSignals[i]);
}

}  // namespace strata

#pragma once
// Ctrl-C (SIGINT) and SIGTERM as a request to stop, not a kill: the handler only records the
// signal, and long work (the bench's frames, the demo, render, track) checks between steps and
// unwinds by throwing Interrupted. Unwinding is what keeps DESIGN.md's "nothing half-written":
// OutputBatch removes its temporaries and folders, and the bench writes the rows it completed,
// marked "interrupted". A second signal while the first unwinds ends the process at once (the
// default action is restored when the first arrives), so a stuck step can still be stopped.
#include <stdexcept>
#include <string>

namespace strata {

class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(int signal);
    int signal() const { return signal_; }
    int exitStatus() const { return 128 + signal_; }  // as a shell reports a process the signal ended

private:
    int signal_;
};

// Installs the SIGINT and SIGTERM handlers (once; later calls do nothing). A signal ignored at
// startup (nohup, a non-interactive shell's background job) is left ignored.
void installInterruptHandlers();

// The signal received since the handlers were installed, 0 for none.
int interruptSignal();

// Throws Interrupted when a signal was received (its message: "interrupted by SIGINT").
void throwIfInterrupted();

// For tests: forget a received signal and re-arm the handlers the first one reset.
void clearInterrupt();

}  // namespace strata

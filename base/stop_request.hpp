// A request to stop the run early, made by SIGINT/SIGTERM (cli/stop_signals.cpp). The signal
// handler only stores the signal number in a lock-free atomic (async-signal-safe); the long
// loops (evaluation steps, render samples, radiosity) poll it and unwind with Interrupted, so
// that destructors remove temporary files on the way out. It lives in the parser library
// because every stage links that one.
#pragma once
#include <stdexcept>

namespace lumen {

// Called from a signal handler: nothing but an atomic store.
void request_stop(int signal) noexcept;
// The signal that asked to stop, or 0.
int stop_requested() noexcept;
// Forgets a request (tests; a library caller that recovered).
void clear_stop_request() noexcept;

struct Interrupted : std::runtime_error {
    int signal;
    explicit Interrupted(int sig);
};

// Throws Interrupted when a stop was requested.
inline void throw_if_stop_requested() {
    if (int sig = stop_requested()) throw Interrupted(sig);
}

}  // namespace lumen

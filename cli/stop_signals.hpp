// SIGINT and SIGTERM during a run: the handler records the signal (parser/stop_request.hpp) and
// does nothing else. Evaluation steps, render samples and radiosity chunks poll the request and
// unwind with Interrupted, which removes the temporary image file on the way (ImageEncoder's
// destructor); lumen then exits with 128 + the signal (130, 143), as shells expect. A second
// signal of the same kind gets the default action, should unwinding ever get stuck.
#pragma once
#include <csignal>

namespace lumen::cli {

class StopSignals {
public:
    StopSignals();   // installs the handlers
    ~StopSignals();  // restores the previous ones
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    struct sigaction saved_interrupt_ = {}, saved_terminate_ = {};
};

// The exit status of a run stopped by `signal`.
inline int stopped_exit_status(int signal) { return 128 + signal; }

}  // namespace lumen::cli

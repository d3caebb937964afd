#include "cli/stop_signals.hpp"

#include "base/stop_request.hpp"

namespace lumen::cli {
namespace {

extern "C" void on_stop_signal(int signal) { request_stop(signal); }

}  // namespace

StopSignals::StopSignals() {
    struct sigaction action = {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    sigaction(SIGINT, &action, &saved_interrupt_);
    sigaction(SIGTERM, &action, &saved_terminate_);
    // A signal ignored when lumen started (a background job of a script, nohup) stays ignored.
    if (saved_interrupt_.sa_handler == SIG_IGN) sigaction(SIGINT, &saved_interrupt_, nullptr);
    if (saved_terminate_.sa_handler == SIG_IGN) sigaction(SIGTERM, &saved_terminate_, nullptr);
}

StopSignals::~StopSignals() {
    sigaction(SIGINT, &saved_interrupt_, nullptr);
    sigaction(SIGTERM, &saved_terminate_, nullptr);
}

}  // namespace lumen::cli

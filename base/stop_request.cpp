#include "base/stop_request.hpp"

#include <atomic>
#include <string>

namespace lumen {
namespace {

std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

}  // namespace

void request_stop(int signal) noexcept { g_stop_signal.store(signal, std::memory_order_relaxed); }

int stop_requested() noexcept { return g_stop_signal.load(std::memory_order_relaxed); }

void clear_stop_request() noexcept { g_stop_signal.store(0, std::memory_order_relaxed); }

Interrupted::Interrupted(int sig)
    : std::runtime_error("interrupted by signal " + std::to_string(sig)), signal(sig) {}

}  // namespace lumen

// Runs work on a thread with a large stack, so deep but legal recursion in the interpreter or
// the tracer (nested CSG, recursive macros) cannot overflow the main thread's 8 MiB.
#pragma once
#include <cstddef>
#include <functional>

namespace lumen::cli {

constexpr std::size_t kBigStackBytes = std::size_t(512) << 20;

// Calls `work` on a new thread with `stack_bytes` of stack and waits for it. An exception
// thrown by `work` is rethrown here. Falls back to the calling thread if no thread can be made.
void run_with_big_stack(const std::function<void()>& work, std::size_t stack_bytes = kBigStackBytes);

}  // namespace lumen::cli

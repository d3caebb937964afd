// Bounds on one evaluation, so that a runaway scene (an endless #while, a string doubled in a
// loop, exponential macro recursion) ends with a located error naming the limit instead of
// hanging or exhausting memory. POV-Ray itself has no such limits: it runs until killed.
#pragma once
#include <cstddef>
#include <string>

#include "interp/interpret.hpp"

namespace lumen::interp {

class Budget {
public:
    explicit Budget(const InterpOptions& options) : options_(options) {}

    // One unit of unbounded work (a loop iteration, a macro or function call) at `where`:
    // counts it against max_steps, polls the stop request (SIGINT/SIGTERM) and now and then
    // measures the heap.
    void step(SourceLoc where);
    // A string of `length` bytes was just built at `where` (concat): the per-string limit,
    // and the bytes count towards the next heap measurement.
    void string_built(size_t length, SourceLoc where);
    // About to allocate `bytes` at `where` (an array): the heap must stay under max_memory.
    void allocating(size_t bytes, SourceLoc where);

    long long steps() const { return steps_; }

    // Heap bytes in use by this process (malloc's count; ASan's allocator under ASan).
    static size_t heap_in_use();

private:
    void check_memory(size_t extra, SourceLoc where);

    const InterpOptions& options_;
    long long steps_ = 0;
    size_t bytes_since_check_ = 0;
};

// "16 MiB", "4 GiB", "512 bytes": limits in messages.
std::string size_text(size_t bytes);

}  // namespace lumen::interp

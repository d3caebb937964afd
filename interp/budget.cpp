#include "interp/budget.hpp"

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "base/diagnostics.hpp"
#include "base/stop_request.hpp"

#include "base/sanitizers.hpp"
#if LUMEN_ASAN
#include <sanitizer/allocator_interface.h>
#endif

namespace lumen::interp {
namespace {

// Measuring the heap costs a few microseconds: do it every this many steps, or sooner once
// this many string bytes were built since the last measurement.
constexpr long long kStepsPerMeasure = 4096;
constexpr size_t kBytesPerMeasure = size_t(64) << 20;

}  // namespace

std::string size_text(size_t bytes) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
    double v = double(bytes);
    int u = 0;
    while (v >= 1024 && u < 4) v /= 1024, ++u;
    char buf[32];
    std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.3g %s", v, units[u]);
    return buf;
}

size_t default_max_memory() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    const size_t cap = size_t(8) << 30;
    if (pages <= 0 || page <= 0) return cap;
    return std::min(cap, size_t(pages) * size_t(page) / 2);
}

size_t Budget::heap_in_use() {
#if LUMEN_ASAN
    return __sanitizer_get_current_allocated_bytes();
#else
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;  // in-use arena chunks plus mmapped blocks
#endif
}

void Budget::step(SourceLoc where) {
    throw_if_stop_requested();
    if (++steps_ > options_.max_steps)
        throw LumenError(where, "the scene took more than " + std::to_string(options_.max_steps) +
                                    " evaluation steps (loop iterations and macro/function calls; "
                                    "limit Max_Eval_Steps): an endless loop or recursion?");
    if (steps_ % kStepsPerMeasure == 0) check_memory(0, where);
}

void Budget::string_built(size_t length, SourceLoc where) {
    if (length > options_.max_string_length)
        throw LumenError(where, "string of " + std::to_string(length) + " bytes exceeds the limit of " +
                                    size_text(options_.max_string_length) +
                                    " per string (Max_String_Length)");
    bytes_since_check_ += length;
    if (bytes_since_check_ >= kBytesPerMeasure) check_memory(0, where);
}

void Budget::allocating(size_t bytes, SourceLoc where) { check_memory(bytes, where); }

void Budget::check_memory(size_t extra, SourceLoc where) {
    bytes_since_check_ = 0;
    if (options_.max_memory == 0) return;
    const size_t used = heap_in_use();
    if (used > options_.max_memory || extra > options_.max_memory - used)
        throw LumenError(where, "evaluating the scene needs more than " + size_text(options_.max_memory) +
                                    " of memory (limit Max_Eval_Memory; " + size_text(used) +
                                    " in use" + (extra ? ", " + size_text(extra) + " more asked for here" : std::string()) +
                                    ")");
}

}  // namespace lumen::interp

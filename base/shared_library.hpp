// Libraries only some scenes need, opened at their first use instead of linked: every run of
// lumen would otherwise pay their loading at start-up (measured with `perf stat` on an empty
// program: Embree with TBB about 5 ms, FreeType with its codecs about 4 ms; lumen's own start
// is about 3 ms), which is most of a `--check` of a small scene.
#pragma once
#include <string>

namespace lumen::base {

// The library `name` (a soname such as "libembree3.so.3", or a path), opened once per process
// for every caller; null with `why` set where it cannot be opened.
void* open_library(const std::string& name, std::string& why);

// The address of `symbol` in an opened library; null with `why` set where it has none.
void* library_symbol(void* library, const char* symbol, std::string& why);

}  // namespace lumen::base

// A table of a library's C functions, one member per name, typed as the library's header
// declares it: struct Api { LUMEN_LIBRARY_FUNCTIONS(MEMBER) }; with
//   #define MEMBER(f) LUMEN_LIBRARY_MEMBER(f)
// and filled by LUMEN_LIBRARY_RESOLVE(api, library, why) for each name.
#define LUMEN_LIBRARY_MEMBER(f) decltype(&::f) f = nullptr;
#define LUMEN_LIBRARY_RESOLVE(api, library, why, f)                                     \
    ((api).f = reinterpret_cast<decltype(&::f)>(::lumen::base::library_symbol(library, #f, why)))

// Libraries only some scenes need, opened at their first use instead of linked: every run of
// lumen would otherwise pay their loading at start-up (an empty program linked with Embree and
// TBB starts in 5.9 ms against 1.7 ms without, minimum of 60 runs), which is a large part of
// a `--check` of a small scene.
#pragma once
#include <string>

namespace lumen::base {

// The library `name` (a soname such as "libembree3.so.3", or a path), opened once per process
// for every caller; null with `why` set where it cannot be opened.
void* open_library(const std::string& name, std::string& why);

// The address of `symbol` in an opened library; null with `why` set where it has none.
void* library_symbol(void* library, const char* symbol, std::string& why);

}  // namespace lumen::base

// A struct `Name` holding a library's C functions, one member per name of the X-macro LIST,
// typed as the library's header declares it, with resolve(library, why) filling them:
//   #define MY_FUNCTIONS(X) X(lib_open) X(lib_close)
//   LUMEN_LIBRARY_API(MyLib, MY_FUNCTIONS)
//   const MyLib* api = lumen::base::library_api<MyLib>("libmy.so.1", why);
#define LUMEN_LIBRARY_MEMBER(f) decltype(&::f) f = nullptr;
#define LUMEN_LIBRARY_RESOLVE(f) \
    ok = ok && (f = reinterpret_cast<decltype(f)>(::lumen::base::library_symbol(library, #f, why)));
#define LUMEN_LIBRARY_API(Name, LIST)                   \
    struct Name {                                       \
        LIST(LUMEN_LIBRARY_MEMBER)                      \
        bool resolve(void* library, std::string& why) { \
            bool ok = library != nullptr;               \
            LIST(LUMEN_LIBRARY_RESOLVE)                 \
            return ok;                                  \
        }                                               \
    };

namespace lumen::base {

// The functions of `Api` (made by LUMEN_LIBRARY_API) from library `name`, resolved once per
// process; null with `why` set where the library cannot be opened or lacks one of them (a
// found library costs its callers one test per call: FreeType's are made per glyph).
template <class Api>
const Api* library_api(const char* name, std::string& why) {
    static std::string error;
    static const Api* api = [name]() -> const Api* {
        static Api functions;
        return functions.resolve(open_library(name, error), error) ? &functions : nullptr;
    }();
    if (!api) why = error;
    return api;
}

}  // namespace lumen::base

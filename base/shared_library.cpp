// Libraries opened on demand (shared_library.hpp).
#include "base/shared_library.hpp"

#include <dlfcn.h>

#include <map>
#include <mutex>
#include <utility>

namespace lumen::base {

void* open_library(const std::string& name, std::string& why) {
    static std::mutex mutex;
    // Each name is tried once: a library that failed to open is not retried per object.
    static std::map<std::string, std::pair<void*, std::string>> opened;
    const std::lock_guard lock(mutex);
    auto [it, fresh] = opened.try_emplace(name);
    if (fresh) {
        it->second.first = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!it->second.first) {
            const char* error = dlerror();
            it->second.second = error ? error : "cannot open " + name;
        }
    }
    why = it->second.second;
    return it->second.first;
}

void* library_symbol(void* library, const char* symbol, std::string& why) {
    void* address = library ? dlsym(library, symbol) : nullptr;
    if (!address) why = std::string("the library has no ") + symbol;
    return address;
}

}  // namespace lumen::base

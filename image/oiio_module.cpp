// Loads liblumen_oiio.so once, from the folder of the running executable, else from where
// the build put it (LUMEN_OIIO_MODULE, for test programs built elsewhere).
#include "image/oiio_module.hpp"

#include "base/shared_library.hpp"

#include <filesystem>
#include <mutex>
#include <vector>

namespace lumen::image {

namespace {

constexpr const char* kModuleName = "liblumen_oiio.so";

std::filesystem::path executable_folder() {
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : exe.parent_path();
}

// The module's handle, or null with `why` set.
void* module_handle(std::string& why) {
    static std::once_flag once;
    static void* handle = nullptr;
    static std::string error;
    std::call_once(once, [] {
        std::vector<std::string> candidates;
        if (const auto folder = executable_folder(); !folder.empty())
            candidates.push_back((folder / kModuleName).string());
#ifdef LUMEN_OIIO_MODULE
        candidates.push_back(LUMEN_OIIO_MODULE);
#endif
        for (const std::string& path : candidates) {
            if (!std::filesystem::exists(path)) continue;
            handle = base::open_library(path, error);
            if (handle) return;
        }
        if (error.empty()) error = std::string(kModuleName) + " was not found beside lumen";
    });
    why = error;
    return handle;
}

}  // namespace

void* oiio_module_function(const char* symbol, std::string& why) {
    void* handle = module_handle(why);
    if (!handle) return nullptr;
    void* f = base::library_symbol(handle, symbol, why);
    if (!f) why = std::string(kModuleName) + " has no " + symbol;
    return f;
}

}  // namespace lumen::image

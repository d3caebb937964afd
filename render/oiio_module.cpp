// write_with_oiio(): loads liblumen_oiio.so on first use, from the folder of the running
// executable, else from where the build put it.
#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "render/image_files.hpp"
#include "render/oiio/lumen_oiio.h"

namespace lumen::render {
namespace {

constexpr const char* kModuleName = "liblumen_oiio.so";

std::filesystem::path executable_folder() {
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : exe.parent_path();
}

// The writer function, or null with `why` set. Loaded once per process.
LumenOiioWrite load_writer(std::string& why) {
    static std::once_flag once;
    static LumenOiioWrite writer = nullptr;
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
            void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                error = dlerror();
                continue;
            }
            writer = reinterpret_cast<LumenOiioWrite>(dlsym(handle, LUMEN_OIIO_WRITE_SYMBOL));
            if (writer) return;
            error = path + " has no " LUMEN_OIIO_WRITE_SYMBOL;
        }
        if (error.empty()) error = std::string(kModuleName) + " was not found beside lumen";
    });
    why = error;
    return writer;
}

}  // namespace

void write_with_oiio(const EncodedImage& image, const char* format, const std::string& path) {
    std::string why;
    const LumenOiioWrite write = load_writer(why);
    if (!write)
        throw std::runtime_error("the OpenImageIO writer is missing (" + why + ")");
    LumenOiioImage spec{};
    spec.format = format;
    spec.path = path.c_str();
    spec.width = image.width;
    spec.height = image.height;
    spec.channels = image.channels;
    const bool floating = image.maxval == 0;
    spec.stored = floating ? (std::string(format) == "hdr" ? LUMEN_OIIO_FLOAT : LUMEN_OIIO_HALF)
                           : (image.maxval > 255 ? LUMEN_OIIO_UINT16 : LUMEN_OIIO_UINT8);
    if (!floating) spec.colour_space = image.curve == EncodedImage::Curve::Unlabelled ? "" : "sRGB";
    spec.software = "lumen " LUMEN_VERSION;
    // OIIO takes integer files as floats in [0,1]: the exact levels divided by maxval.
    std::vector<float> scaled;
    if (!floating) {
        scaled.reserve(image.values.size());
        for (float v : image.values) scaled.push_back(float(double(v) / image.maxval));
    }
    spec.pixels = floating ? image.values.data() : scaled.data();
    char error[512] = "";
    if (write(&spec, error, sizeof error) != 0)
        throw std::runtime_error(error);
}

}  // namespace lumen::render

// Binary PPM (P6): 8-bit, or 16-bit big-endian samples with maxval 65535. PPM has no alpha.
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include "render/image_files.hpp"

namespace lumen::render {

void write_ppm(const EncodedImage& image, const std::string& path) {
    if (image.channels != 3)
        throw std::runtime_error("PPM has no alpha channel (+UA)");
    const bool sixteen = image.maxval > 255;
    std::vector<uint8_t> bytes;
    bytes.reserve(image.values.size() * (sixteen ? 2 : 1));
    for (float f : image.values) {
        const unsigned v = unsigned(f);
        if (sixteen) bytes.push_back(uint8_t(v >> 8));
        bytes.push_back(uint8_t(v & 0xff));
    }
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"), std::fclose);
    if (!file) throw std::runtime_error(std::strerror(errno));
    const bool written =
        std::fprintf(file.get(), "P6\n%d %d\n%d\n", image.width, image.height, image.maxval) > 0 &&
        std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
    const bool closed = std::fclose(file.release()) == 0;
    if (!written || !closed) throw std::runtime_error("the disk may be full");
}

}  // namespace lumen::render

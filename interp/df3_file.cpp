#include "interp/df3_file.hpp"

#include <fstream>
#include <iterator>
#include <vector>

#include "base/diagnostics.hpp"

namespace lumen::interp {

std::shared_ptr<const scene::pattern::DensityGrid> read_df3(const std::string& path, SourceLoc loc) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw LumenError(loc, "cannot read density file '" + path + "'");
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    auto big_endian = [&](size_t at, int width) {
        unsigned long v = 0;
        for (int i = 0; i < width; ++i) v = v << 8 | bytes[at + i];
        return v;
    };
    if (bytes.size() < 6) throw LumenError(loc, "density file '" + path + "' has no header");
    auto grid = std::make_shared<scene::pattern::DensityGrid>();
    grid->nx = int(big_endian(0, 2));
    grid->ny = int(big_endian(2, 2));
    grid->nz = int(big_endian(4, 2));
    const size_t count = size_t(grid->nx) * grid->ny * grid->nz;
    const size_t data = bytes.size() - 6;
    int width = 0;
    for (int w : {1, 2, 4})
        if (count > 0 && data == count * w) width = w;
    if (width == 0)
        throw LumenError(loc, "density file '" + path + "': " + std::to_string(data) +
                                  " bytes of voxels do not fit " + std::to_string(grid->nx) + "x" +
                                  std::to_string(grid->ny) + "x" + std::to_string(grid->nz));
    const double scale = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0;
    grid->values.resize(count);
    for (size_t i = 0; i < count; ++i) grid->values[i] = double(big_endian(6 + i * width, width)) / scale;
    return grid;
}

}  // namespace lumen::interp

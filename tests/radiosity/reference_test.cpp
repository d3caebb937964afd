// Renders cornell.pov with lumen and compares it with the converged POV-Ray reference: the
// mean absolute error over all pixels and RGB channels (8-bit values on a 0..1 scale, as
// `idiff -a`) must not exceed the floor in the data file. Exit 77 (skip) without the scene.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

namespace {

bool read_rgb8(const std::string& path, int& w, int& h, std::vector<unsigned char>& rgb) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return false;
    const OIIO::ImageSpec& spec = in->spec();
    w = spec.width;
    h = spec.height;
    std::vector<unsigned char> all(size_t(w) * h * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, all.data())) return false;
    rgb.resize(size_t(w) * h * 3);
    for (size_t p = 0; p < size_t(w) * h; ++p)
        for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = all[p * spec.nchannels + std::min(c, spec.nchannels - 1)];
    return true;
}

double read_floor(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty() && line[0] != '#') return std::stod(line);
    return -1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 6) {
        std::fprintf(stderr, "usage: radiosity_cornell LUMEN SCENE REFERENCE FLOOR_FILE OUT\n");
        return 2;
    }
    const std::string lumen = argv[1], scene = argv[2], reference = argv[3], out = argv[5];
    if (!std::filesystem::exists(scene)) {
        std::printf("skipped: %s not installed (package povray-examples)\n", scene.c_str());
        return 77;
    }
    const double floor = read_floor(argv[4]);
    const std::string cmd = "'" + lumen + "' '" + scene + "' +W300 +H300 -A +V +FN '+O" + out + "'";
    const auto t0 = std::chrono::steady_clock::now();
    if (std::system(cmd.c_str()) != 0) {
        std::fprintf(stderr, "lumen failed: %s\n", cmd.c_str());
        return 1;
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    int w1, h1, w2, h2;
    std::vector<unsigned char> a, b;
    if (!read_rgb8(reference, w1, h1, a) || !read_rgb8(out, w2, h2, b) || w1 != w2 || h1 != h2) {
        std::fprintf(stderr, "cannot read or size mismatch: %s %s\n", reference.c_str(), out.c_str());
        return 1;
    }
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) sum += std::abs(int(a[i]) - int(b[i])) / 255.0;
    const double mae = sum / double(a.size());
    std::printf("cornell.pov 300x300: mean absolute error %.5f (floor %.5f), lumen %.2f s wall\n",
                mae, floor, secs);
    return floor > 0 && mae <= floor ? 0 : 1;
}

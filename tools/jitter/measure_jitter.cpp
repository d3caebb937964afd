// measure_jitter: recovers POV-Ray's 256 anti-aliasing jitter offsets by rendering
// tools/jitter/probe.pov with the installed povray, and prints them as the initializer of
// render/jitter_table.cpp (--print) or checks lumen's table against them (--check).
//   measure_jitter --probe tools/jitter/probe.pov [--work DIR] (--print | --check)
// Exit status: 0 ok, 1 mismatch or inconsistent measurement, 2 usage or povray failure,
// 77 when povray is not installed (ctest reports a skip).
//
// How: at +A0.0 +AM1 +R1 +J1 every pixel (px, py) is (centre + one sample)/2, the sample taken
// at (px + jx, py + jy) where jx = table[jitter_index(px, py, 1021, 1019)] and
// jy = table[jitter_index(px, py, 1019, 1021)] (render/jitter.hpp). The probe's red and green
// read frac(0.5 + d/P) at d pixels from the centre, so each pixel gives jx and jy modulo P.
// Periods of 1, 2^-12 and 2^-20 pixel refine each entry in turn (each stage's uncertainty is
// far below the next one's period, so the readings unwrap without ambiguity).
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/jitter.hpp"

namespace {

namespace fs = std::filesystem;
using Table = std::array<double, 256>;

constexpr int kSize = 256;          // probe image side (probe.pov's W and H)
constexpr int kExponents[] = {0, 12, 20};  // ramp periods 2^-E pixel

struct Image16 {
    int width = 0, height = 0;
    std::vector<uint16_t> rgb;
    double channel(int x, int y, int c) const { return rgb[(size_t(y) * width + x) * 3 + c] / 65535.0; }
};

// A binary PPM with 16-bit samples (POV's +FP16).
Image16 read_ppm16(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int maxval = 0;
    Image16 img;
    auto skip_comments = [&] {
        in >> std::ws;
        while (in.peek() == '#') {
            std::string line;
            std::getline(in, line);
            in >> std::ws;
        }
    };
    in >> magic;
    skip_comments();
    in >> img.width;
    skip_comments();
    in >> img.height;
    skip_comments();
    in >> maxval;
    in.get();
    if (!in || magic != "P6" || maxval != 65535 || img.width != kSize || img.height != kSize)
        throw std::runtime_error(path.string() + ": expected a 256x256 16-bit binary PPM");
    std::vector<unsigned char> bytes(size_t(img.width) * img.height * 6);
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!in) throw std::runtime_error(path.string() + ": truncated");
    img.rgb.resize(bytes.size() / 2);
    for (size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = uint16_t(bytes[2 * i] << 8 | bytes[2 * i + 1]);
    return img;
}

Image16 render_probe(const fs::path& probe, const fs::path& work, int exponent) {
    const fs::path out = work / ("probe-E" + std::to_string(exponent) + ".ppm");
    const fs::path log = work / ("probe-E" + std::to_string(exponent) + ".log");
    fs::remove(out);
    const std::string cmd = "cd '" + work.string() + "' && povray -D -V +FP16 File_Gamma=1.0 +W" +
                            std::to_string(kSize) + " +H" + std::to_string(kSize) +
                            " +A0.0 +AM1 +R1 +J1.0 Declare=E=" + std::to_string(exponent) +
                            " '+I" + probe.string() + "' '+O" + out.string() + "' >'" +
                            log.string() + "' 2>&1";
    const int status = std::system(cmd.c_str());
    if (status != 0 || !fs::exists(out))
        throw std::runtime_error("povray failed on " + probe.string() + " (see " + log.string() + ")");
    return read_ppm16(out);
}

// One refinement: every pixel reads jx and jy modulo `period`; each reading is unwrapped to
// the copy nearest the previous estimate of its entry (or, in the first stage, nearest the
// entry's first reading) and the entry becomes the median. `spread` is the largest
// disagreement between pixels that read the same entry.
struct Stage {
    Table value{};
    double spread = 0;
    size_t min_readings = 0;
};

Stage refine(const Image16& img, double period, const Table* previous) {
    std::vector<std::vector<double>> readings(256);
    auto add = [&](int entry, double phase) {  // phase: offset/period, modulo 1
        std::vector<double>& r = readings[entry];
        const double ref = previous ? (*previous)[entry] / period : (r.empty() ? phase : r.front() / period);
        r.push_back((ref + std::remainder(phase - ref, 1.0)) * period);
    };
    for (int py = 0; py < img.height; ++py) {
        for (int px = 0; px < img.width; ++px) {
            // value = (0.5 + ramp)/2 and ramp = frac(0.5 + offset/period).
            const double rx = 2 * img.channel(px, py, 0) - 0.5;
            const double ry = 2 * img.channel(px, py, 1) - 0.5;
            add(lumen::render::jitter_index(px, py, 1021, 1019), rx - 0.5);
            add(lumen::render::jitter_index(px, py, 1019, 1021), -(ry - 0.5));  // image y runs down
        }
    }
    Stage s;
    s.min_readings = readings[0].size();
    for (int k = 0; k < 256; ++k) {
        std::vector<double>& r = readings[k];
        s.min_readings = std::min(s.min_readings, r.size());
        if (r.empty()) throw std::runtime_error("entry " + std::to_string(k) + " was never read");
        std::sort(r.begin(), r.end());
        s.value[k] = r[r.size() / 2];
        s.spread = std::max(s.spread, r.back() - r.front());
    }
    return s;
}

struct Measurement {
    Table value{};
    double resolution = 0;  // one 16-bit level of the last stage, in pixels
    bool consistent = true;
};

Measurement measure(const fs::path& probe, const fs::path& work) {
    Measurement m;
    const Table* previous = nullptr;
    for (int e : kExponents) {
        const double period = std::ldexp(1.0, -e);
        const double level = 2 * period / 65535;  // one 16-bit level of the reading
        const Stage s = refine(render_probe(probe, work, e), period, previous);
        std::fprintf(stderr, "period 2^-%-2d: >= %zu pixels per entry, largest disagreement %.3g (%.2f levels)\n",
                     e, s.min_readings, s.spread, s.spread / level);
        m.consistent = m.consistent && s.spread <= 2 * level;
        m.value = s.value;
        m.resolution = level;
        previous = &m.value;
    }
    // The table spans [−0.5, 0.5): an entry read as +0.5 is −0.5 seen across the ramp's wrap.
    for (double& v : m.value)
        if (v > 0.5 - 1e-6) v -= 1;
    return m;
}

int print_table(const Measurement& m) {
    int undecimal = 0;
    for (int k = 0; k < 256; ++k) {
        // Every entry measured so far is the float nearest a 6-decimal number: print that.
        const double decimal = std::round(m.value[k] * 1e6) / 1e6;
        const bool fits = std::fabs(double(float(decimal)) - m.value[k]) <= 2 * m.resolution;
        undecimal += !fits;
        std::printf(k % 8 ? " " : "        ");
        std::printf(fits ? "%9.6ff," : "%.9gf,", fits ? decimal : m.value[k]);
        if (k % 8 == 7) std::printf("\n");
    }
    std::fprintf(stderr, "%d of 256 entries are not a float of a 6-decimal number\n", undecimal);
    return m.consistent ? 0 : 1;
}

int check_table(const Measurement& m) {
    const std::array<float, 256>& table = lumen::render::jitter_table();
    double worst = 0;
    int worst_k = 0;
    for (int k = 0; k < 256; ++k) {
        const double d = std::fabs(double(table[k]) - m.value[k]);
        if (d > worst) worst = d, worst_k = k;
    }
    const bool ok = m.consistent && worst <= 3 * m.resolution;
    std::printf("lumen's jitter table vs POV-Ray's measured: largest difference %.3g at entry %d "
                "(allowed %.3g)%s: %s\n",
                worst, worst_k, 3 * m.resolution, m.consistent ? "" : "; the measurement is inconsistent",
                ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    std::map<std::string, std::string> args;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--print" || a == "--check")
            args[a.substr(2)] = "1";
        else if ((a == "--probe" || a == "--work") && i + 1 < argc)
            args[a.substr(2)] = argv[++i];
        else
            args["bad"] = a;
    }
    if (args.count("bad") || !args.count("probe") || args.count("print") == args.count("check")) {
        std::fprintf(stderr, "usage: measure_jitter --probe tools/jitter/probe.pov [--work DIR] (--print | --check)\n");
        return 2;
    }
    if (std::system("command -v povray >/dev/null 2>&1") != 0) {
        std::fprintf(stderr, "povray is not installed: nothing to measure\n");
        return 77;
    }
    try {
        const fs::path probe = fs::absolute(args["probe"]);
        const fs::path work = fs::absolute(args.count("work") ? args["work"] : "measure_jitter_work");
        fs::create_directories(work);
        const Measurement m = measure(probe, work);
        return args.count("print") ? print_table(m) : check_table(m);
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "measure_jitter: %s\n", ex.what());
        return 2;
    }
}

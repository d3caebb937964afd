// Stability test driver: renders one scene of tests/stability with the lumen program and checks
// the expectations written in the scene's header comments, one per line:
//   // expect: size WxH                   image size (default 64x48), rendered with -A
//   // expect: uniform X0 Y0 X1 Y1 R G B T every pixel of the inclusive rectangle is within T
//                                         of the linear colour <R,G,B> (plus half-float rounding)
//   // expect: same X0 Y0 X1 Y1           every pixel of the rectangle equals its first pixel
//   // expect: mirror-x T | mirror-y T    the image equals its left-right / top-bottom mirror
//   // expect: colours R G B [R G B ...]  every pixel is one of these linear colours (flat
//                                         shading: a grazing hit must not make a new colour)
//   // expect: povray DB                  POV-Ray's render of the same file (8-bit PNG, same
//                                         size) is matched to at least DB PSNR
//   // expect: error LINE:COL TEXT        lumen exits non-zero, reports "SCENE:LINE:COL:
//                                         error: TEXT", and leaves no file behind
// A successful render is written as OpenEXR (linear, half float) and every value must be
// finite: no NaN or infinite pixel.
//   stability --lumen LUMEN --scene FILE --out DIR
// Exit status: 0 pass, 1 fail, 2 bad arguments or a malformed expectation.
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "tests/differential/image_compare.hpp"
#include "tests/differential/shell.hpp"

namespace {

namespace fs = std::filesystem;
using lumen::differential::quote;
using lumen::differential::read_text;

struct Expectation {
    std::string kind;
    std::vector<double> numbers;
    std::string text;  // error: the message; others: the line as written
    int line = 0;
};

struct Scene {
    fs::path path;
    int width = 64, height = 48;
    std::vector<Expectation> expectations;
};

// Runs `command` in `dir` with stdout and stderr in `log`; returns the exit status (128 + the
// signal when it crashed).
int run_in(const fs::path& dir, const std::string& command, const fs::path& log) {
    const std::string full = "cd " + quote(dir.string()) + " && " + command + " >" +
                             quote(log.string()) + " 2>&1";
    const int status = std::system(full.c_str());
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

Scene read_scene(const fs::path& path) {
    Scene s;
    s.path = path;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    const std::string tag = "// expect:";
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.rfind(tag, 0) != 0) continue;
        std::istringstream words(line.substr(tag.size()));
        Expectation e;
        e.line = n;
        words >> e.kind;
        auto fail = [&](const std::string& why) {
            throw std::runtime_error(path.string() + ":" + std::to_string(n) + ": " + why);
        };
        if (e.kind == "size") {
            char x = 0;
            if (!(words >> s.width >> x >> s.height) || x != 'x' || s.width < 1 || s.height < 1)
                fail("expected 'size WxH'");
            continue;
        }
        if (e.kind == "error") {
            std::string at;
            words >> at;
            std::getline(words >> std::ws, e.text);
            if (at.find(':') == std::string::npos || e.text.empty())
                fail("expected 'error LINE:COL MESSAGE'");
            e.text = path.filename().string() + ":" + at + ": error: " + e.text;
        } else {
            const std::map<std::string, size_t> arity = {{"uniform", 8}, {"same", 4},
                                                         {"mirror-x", 1}, {"mirror-y", 1},
                                                         {"povray", 1}};
            const auto it = arity.find(e.kind);
            if (it == arity.end() && e.kind != "colours")
                fail("unknown expectation '" + e.kind + "'");
            double v = 0;
            while (words >> v) e.numbers.push_back(v);
            if (e.kind == "colours" && (e.numbers.empty() || e.numbers.size() % 3 != 0))
                fail("'colours' takes R G B triples");
            if (e.kind != "colours" && e.numbers.size() != it->second)
                fail("'" + e.kind + "' takes " + std::to_string(it->second) + " numbers");
            e.text = line;
        }
        s.expectations.push_back(e);
    }
    if (s.expectations.empty()) throw std::runtime_error(path.string() + ": no expectations");
    return s;
}

struct FloatImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> values;
    const float* at(int x, int y) const {
        return &values[(size_t(y) * width + x) * size_t(channels)];
    }
};

FloatImage load_float(const fs::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw std::runtime_error("cannot read image " + path.string());
    const OIIO::ImageSpec& spec = in->spec();
    FloatImage img{spec.width, spec.height, spec.nchannels, {}};
    img.values.resize(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.values.data()))
        throw std::runtime_error("cannot decode image " + path.string());
    return img;
}

class Checker {
public:
    explicit Checker(const Scene& s) : scene_(s) {}
    bool failed() const { return failed_; }

    void fail(const Expectation& e, const std::string& why) {
        std::printf("FAIL %s:%d: %s\n  %s\n", scene_.path.filename().c_str(), e.line,
                    e.text.c_str(), why.c_str());
        failed_ = true;
    }

    void check_finite(const FloatImage& img) {
        int bad = 0;
        std::string first;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                for (int c = 0; c < img.channels; ++c)
                    if (!std::isfinite(img.at(x, y)[c]) && bad++ == 0)
                        first = "(" + std::to_string(x) + "," + std::to_string(y) + ")";
        if (bad) {
            std::printf("FAIL %s: %d non-finite values, first at pixel %s\n",
                        scene_.path.filename().c_str(), bad, first.c_str());
            failed_ = true;
        }
    }

    // Half floats keep 11 significant bits.
    static bool near(double v, double want, double tol) {
        return std::fabs(v - want) <= tol + std::fabs(want) / 2048;
    }

    void check_image(const Expectation& e, const FloatImage& img) {
        const std::vector<double>& n = e.numbers;
        if (e.kind == "colours") {
            for (int y = 0; y < img.height; ++y)
                for (int x = 0; x < img.width; ++x) {
                    const float* p = img.at(x, y);
                    bool known = false;
                    for (size_t k = 0; k + 2 < n.size() && !known; k += 3)
                        known = near(p[0], n[k], 0) && near(p[1], n[k + 1], 0) &&
                                near(p[2], n[k + 2], 0);
                    if (!known)
                        return fail(e, "pixel (" + std::to_string(x) + "," + std::to_string(y) +
                                           ") is " + std::to_string(p[0]) + " " +
                                           std::to_string(p[1]) + " " + std::to_string(p[2]));
                }
        } else if (e.kind == "uniform" || e.kind == "same") {
            const int x0 = int(n[0]), y0 = int(n[1]), x1 = int(n[2]), y1 = int(n[3]);
            if (x0 < 0 || y0 < 0 || x1 >= img.width || y1 >= img.height || x0 > x1 || y0 > y1)
                return fail(e, "rectangle outside the image");
            const float* first = img.at(x0, y0);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x)
                    for (int c = 0; c < 3; ++c) {
                        const double v = img.at(x, y)[c];
                        const bool same = e.kind == "same";
                        const double want = same ? first[c] : n[4 + c];
                        if (same ? v != want : !near(v, want, n[7]))
                            return fail(e, "pixel (" + std::to_string(x) + "," +
                                               std::to_string(y) + ") channel " +
                                               std::to_string(c) + " is " + std::to_string(v) +
                                               ", expected " + std::to_string(want));
                    }
        } else if (e.kind == "mirror-x" || e.kind == "mirror-y") {
            const bool horizontal = e.kind == "mirror-x";
            for (int y = 0; y < img.height; ++y)
                for (int x = 0; x < img.width; ++x) {
                    const int mx = horizontal ? img.width - 1 - x : x;
                    const int my = horizontal ? y : img.height - 1 - y;
                    for (int c = 0; c < 3; ++c)
                        if (!(std::fabs(img.at(x, y)[c] - img.at(mx, my)[c]) <= n[0]))
                            return fail(e, "pixel (" + std::to_string(x) + "," +
                                               std::to_string(y) + ") differs from (" +
                                               std::to_string(mx) + "," + std::to_string(my) + ")");
                }
        }
    }

private:
    const Scene& scene_;
    bool failed_ = false;
};

std::string size_options(const Scene& s) {
    return "+W" + std::to_string(s.width) + " +H" + std::to_string(s.height) + " -A";
}

void check_povray(Checker& check, const Expectation& e, const Scene& s, const fs::path& dir,
                  const std::string& lumen) {
    if (std::system("command -v povray >/dev/null 2>&1") != 0) {
        std::printf("note: povray is not installed: '%s' not checked\n", e.text.c_str());
        return;
    }
    const fs::path ref = dir / "povray.png", ours = dir / "lumen.png";
    const std::string scene = quote(s.path.string());
    if (run_in(dir, "povray -D -V +FN " + size_options(s) + " +I" + scene + " +O" +
                        quote(ref.string()),
               dir / "povray.log") != 0 ||
        !fs::exists(ref))
        return check.fail(e, "povray failed:\n" + read_text(dir / "povray.log"));
    if (run_in(dir, quote(lumen) + " " + scene + " " + size_options(s) + " +FN +O" +
                        quote(ours.string()),
               dir / "lumen-png.log") != 0)
        return check.fail(e, "lumen failed:\n" + read_text(dir / "lumen-png.log"));
    const auto c = lumen::differential::compare_images(ref.string(), ours.string(),
                                                       (dir / "difference.png").string());
    std::printf("%s: PSNR against POV-Ray %.2f dB (floor %.0f), max error %d\n",
                s.path.filename().c_str(), c.psnr, e.numbers[0], c.max_error);
    if (!(c.psnr >= e.numbers[0])) check.fail(e, "PSNR " + std::to_string(c.psnr) + " dB");
}

// A scene lumen must refuse: non-zero exit, the expected diagnostic, and no file written.
void check_error(Checker& check, const Expectation& e, const Scene& s, const fs::path& dir,
                 const std::string& lumen) {
    const fs::path image_dir = dir / "image";
    fs::create_directories(image_dir);
    const int status =
        run_in(dir, quote(lumen) + " " + quote(s.path.string()) + " " + size_options(s) +
                        " +FE +O" + quote((image_dir / "out.exr").string()),
               dir / "lumen.log");
    const std::string log = read_text(dir / "lumen.log");
    if (status == 0) check.fail(e, "lumen exited with 0");
    if (status >= 128) check.fail(e, "lumen crashed (status " + std::to_string(status) + ")");
    if (log.find(e.text) == std::string::npos) check.fail(e, "diagnostic not found in:\n" + log);
    if (!fs::is_empty(image_dir)) check.fail(e, "lumen left a file in " + image_dir.string());
}

int run(const Scene& s, const fs::path& out, const std::string& lumen) {
    const fs::path dir = out / s.path.stem();
    fs::remove_all(dir);
    fs::create_directories(dir);
    Checker check(s);
    bool rendered = false;
    FloatImage img;
    for (const Expectation& e : s.expectations) {
        if (e.kind == "error") {
            check_error(check, e, s, dir, lumen);
            continue;
        }
        if (e.kind == "povray") {
            check_povray(check, e, s, dir, lumen);
            continue;
        }
        if (!rendered) {
            rendered = true;
            const fs::path exr = dir / "lumen.exr";
            const int status = run_in(dir, quote(lumen) + " " + quote(s.path.string()) + " " +
                                               size_options(s) + " +FE +O" + quote(exr.string()),
                                      dir / "lumen.log");
            if (status != 0 || !fs::exists(exr)) {
                check.fail(e, "lumen failed (status " + std::to_string(status) + "):\n" +
                                  read_text(dir / "lumen.log"));
                break;
            }
            img = load_float(exr);
            if (img.width != s.width || img.height != s.height || img.channels < 3) {
                check.fail(e, "unexpected image size or channels");
                break;
            }
            check.check_finite(img);
        }
        check.check_image(e, img);
    }
    std::printf("%s %s\n", s.path.filename().c_str(), check.failed() ? "FAIL" : "PASS");
    return check.failed() ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::map<std::string, std::string> args;
    for (int i = 1; i + 1 < argc; i += 2) args[argv[i]] = argv[i + 1];
    if (!args.count("--lumen") || !args.count("--scene") || !args.count("--out")) {
        std::cerr << "usage: stability --lumen LUMEN --scene FILE.pov --out DIR\n";
        return 2;
    }
    try {
        const Scene s = read_scene(fs::absolute(args["--scene"]));
        return run(s, fs::absolute(args["--out"]), args["--lumen"]);
    } catch (const std::exception& ex) {
        std::cerr << "stability: " << ex.what() << "\n";
        return 2;
    }
}

// Differential test driver: renders one scene of scenes.txt with lumen and with POV-Ray, compares
// them over 8-bit RGB and checks the scene's PSNR floor.
//   differential --list scenes.txt --root REPO --out DIR --lumen LUMEN (--scene NAME | --all)
//   differential --compare REFERENCE CANDIDATE HEAT_MAP   (one comparison, for tools/corpus)
// Exit status: 0 pass, 1 fail, 77 when POV-Ray is not installed (ctest reports a skip).
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "tests/differential/image_compare.hpp"
#include "tests/differential/report.hpp"
#include "tests/differential/shell.hpp"
#include "tests/differential/scene_list.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lumen::differential;

constexpr int kSkip = 77;
const char* const kPovrayScenes = "/usr/share/povray-3.7/scenes";

// Runs a shell command in `dir`, with its output in `log`; returns the exit status and the
// wall time.
std::pair<int, double> run_in(const fs::path& dir, const std::string& command, const fs::path& log) {
    const std::string full = "cd " + quote(dir.string()) + " && " + command + " >" +
                             quote(log.string()) + " 2>&1";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(full.c_str());
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : 128, secs};
}

std::string common_options(const SceneEntry& e) {
    std::string opts = "+W" + std::to_string(e.width) + " +H" + std::to_string(e.height);
    for (const std::string& o : e.options) opts += " " + quote(o);
    return opts + " +L" + quote(fs::path(e.path).parent_path().string());
}

// The reference image depends on the scene text, its size and options: hash them all.
std::string reference_key(const SceneEntry& e) {
    std::string material = read_text(e.path) + "|" + common_options(e);
    uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (unsigned char c : material) h = (h ^ c) * 1099511628211ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

// Renders the POV-Ray reference unless it is cached. Returns the render time (cached too).
double povray_reference(const SceneEntry& e, const fs::path& ref_png, std::string& error) {
    const fs::path time_file = fs::path(ref_png).replace_extension(".seconds");
    if (fs::exists(ref_png) && fs::exists(time_file)) return std::strtod(read_text(time_file).c_str(), nullptr);
    // A private folder: POV-Ray writes its output (and may write other files) beside it.
    const fs::path tmp = fs::path(ref_png).parent_path() / ("tmp-" + e.name);
    fs::create_directories(tmp);
    // Debian's povray also reads /etc/povray/3.7/povray.ini (800x600, display on, library
    // paths): the explicit switches here override what matters.
    const std::string cmd = "povray -D -V +FN " + common_options(e) + " +I" + quote(e.path) +
                            " +O" + quote((tmp / "ref.png").string());
    const auto [status, secs] = run_in(tmp, cmd, tmp / "povray.log");
    if (status != 0 || !fs::exists(tmp / "ref.png")) {
        error = "povray failed (status " + std::to_string(status) + "):\n" + read_text(tmp / "povray.log");
        return 0;
    }
    fs::rename(tmp / "ref.png", ref_png);
    std::ofstream(time_file) << secs << "\n";
    fs::remove_all(tmp);
    return secs;
}

int run_scene(const SceneEntry& e, const fs::path& out, const std::string& lumen,
              const std::vector<std::string>& listed) {
    if (std::system("command -v povray >/dev/null 2>&1") != 0) {
        std::cout << "povray is not installed: skipping " << e.name << "\n";
        return kSkip;
    }
    fs::create_directories(out / "ref");
    fs::create_directories(out / "lumen");
    Result r;
    r.name = e.name;
    r.scene = e.scene;
    r.min_psnr = e.min_psnr;
    for (const std::string& o : e.options) r.options += (r.options.empty() ? "" : " ") + o;
    const std::string ref_rel = "ref/" + e.name + "-" + reference_key(e) + ".png";
    r.povray_seconds = povray_reference(e, out / ref_rel, r.message);
    if (r.message.empty()) {
        r.reference_image = ref_rel;
        r.lumen_image = "lumen/" + e.name + ".png";
        const fs::path lumen_out = out / r.lumen_image;
        fs::remove(lumen_out);
        const std::string cmd = quote(lumen) + " " + quote(e.path) + " " + common_options(e) +
                                " +O" + quote(lumen_out.string());
        const fs::path log = out / "lumen" / (e.name + ".log");
        const auto [status, secs] = run_in(out / "lumen", cmd, log);
        r.lumen_seconds = secs;
        if (status != 0 || !fs::exists(lumen_out)) {
            r.message = "lumen failed (status " + std::to_string(status) + "):\n" + read_text(log);
        } else {
            try {
                r.heat_map = "lumen/" + e.name + "-diff.png";
                const Comparison c = compare_images((out / ref_rel).string(), lumen_out.string(),
                                                    (out / r.heat_map).string());
                r.psnr = c.psnr;
                r.max_error = c.max_error;
                r.differing_fraction = c.differing_fraction;
                r.passed = c.psnr >= e.min_psnr;
            } catch (const std::exception& ex) {
                r.message = ex.what();
                r.heat_map.clear();
            }
        }
    }
    record_result(out.string(), r, listed);
    std::printf("%-40s PSNR %8.2f dB (floor %.0f)  max error %3d  lumen %.2f s  povray %.2f s  %s\n",
                e.name.c_str(), r.psnr, e.min_psnr, r.max_error, r.lumen_seconds, r.povray_seconds,
                r.passed ? "PASS" : "FAIL");
    if (!r.message.empty()) std::printf("%s\n", r.message.c_str());
    std::printf("report: %s\n", (out / "index.html").string().c_str());
    return r.passed ? 0 : 1;
}

// Prints "PSNR MAX_ERROR DIFFERING_FRACTION MEAN_ERROR DARK_WHERE_LIT" of two images (PSNR
// "inf" when identical; image_compare.hpp).
int compare_only(const std::string& reference, const std::string& candidate, const std::string& heat) {
    try {
        const Comparison c = compare_images(reference, candidate, heat);
        std::printf("%.4f %d %.6f %.6f %d\n", c.psnr, c.max_error, c.differing_fraction,
                    c.mean_error, c.dark_where_lit);
        return 0;
    } catch (const std::exception& ex) {
        std::cerr << "differential: " << ex.what() << "\n";
        return 2;
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 5 && std::string(argv[1]) == "--compare") return compare_only(argv[2], argv[3], argv[4]);
    std::map<std::string, std::string> args;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--all") {
            args["all"] = "1";
        } else if (a.rfind("--", 0) == 0 && i + 1 < argc) {
            args[a.substr(2)] = argv[++i];
        } else {
            std::cerr << "differential: unexpected argument '" << a << "'\n";
            return 2;
        }
    }
    for (const char* need : {"list", "root", "out", "lumen"}) {
        if (!args.count(need)) {
            std::cerr << "usage: differential --list scenes.txt --root REPO --out DIR --lumen "
                         "LUMEN (--scene NAME | --all)\n";
            return 2;
        }
    }
    try {
        const auto entries = read_scene_list(args["list"], args["root"], kPovrayScenes);
        std::vector<std::string> listed;
        for (const SceneEntry& e : entries) listed.push_back(e.name);
        int failures = 0, matched = 0;
        for (const SceneEntry& e : entries) {
            if (!args.count("all") && e.name != args["scene"] && e.scene != args["scene"]) continue;
            ++matched;
            const int status = run_scene(e, args["out"], args["lumen"], listed);
            if (status == kSkip) return kSkip;
            failures += status != 0;
        }
        if (matched == 0) {
            std::cerr << "differential: no scene '" << args["scene"] << "' in " << args["list"] << "\n";
            return 2;
        }
        return failures ? 1 : 0;
    } catch (const std::exception& ex) {
        std::cerr << "differential: " << ex.what() << "\n";
        return 2;
    }
}

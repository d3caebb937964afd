// SIGINT/SIGTERM end to end (cli/stop_signals.hpp): lumen renders a slow scene, gets the signal
// once its temporary PNG exists (the render has begun), and must exit within 1.5 s with
// 128 + the signal, leaving no file in its output folder. With --during-parse the signal comes
// while an endless loop is evaluated instead.
//   interrupt --lumen LUMEN --signal INT|TERM [--during-parse] --out DIR
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Many reflective, refractive spheres at 2000x2000 with anti-aliasing: minutes of work.
const char* kSlowScene =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 max_trace_level 20 }\n"
    "camera { location <0, 2, -12> look_at 0 }\n"
    "light_source { <5, 10, -5> rgb 1 area_light x, z, 8, 8 }\n"
    "#for (I, -5, 5) #for (J, -5, 5)\n"
    "  sphere { <I, 0, J>, 0.45 pigment { rgbf <1, 1, 1, 0.8> } finish { reflection 0.5 }\n"
    "           interior { ior 1.5 } }\n"
    "#end #end\n"
    "plane { y, -1 pigment { checker } finish { reflection 0.3 } }\n";

const char* kEndlessScene = "#declare N = 0;\n#while (1) #declare N = N + 1; #end\n";

int fail(const std::string& why) {
    std::fprintf(stderr, "FAIL: %s\n", why.c_str());
    return 1;
}

bool wait_until(const std::function<bool()>& done, double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return done();
}

}  // namespace

int main(int argc, char** argv) {
    std::string lumen, sig_name, out;
    bool during_parse = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--lumen" && i + 1 < argc) lumen = argv[++i];
        else if (a == "--signal" && i + 1 < argc) sig_name = argv[++i];
        else if (a == "--out" && i + 1 < argc) out = argv[++i];
        else if (a == "--during-parse") during_parse = true;
    }
    const int sig = sig_name == "INT" ? SIGINT : sig_name == "TERM" ? SIGTERM : 0;
    if (lumen.empty() || out.empty() || !sig) return fail("usage: interrupt --lumen L --signal INT|TERM --out DIR");
    const fs::path dir = fs::path(out) / ("interrupt_" + sig_name + (during_parse ? "_parse" : "_render"));
    fs::remove_all(dir);
    fs::create_directories(dir / "img");
    const fs::path scene = dir / "scene.pov", log = dir / "lumen.log";
    std::ofstream(scene) << (during_parse ? kEndlessScene : kSlowScene);
    const fs::path image = dir / "img" / "out.png", tmp = dir / "img" / ".out.png.lumen-tmp.png";

    const pid_t pid = fork();
    if (pid < 0) return fail("fork failed");
    if (pid == 0) {
        FILE* f = std::fopen(log.c_str(), "w");
        if (f) dup2(fileno(f), 1), dup2(fileno(f), 2);
        const std::string o = "+O" + image.string();
        execl(lumen.c_str(), lumen.c_str(), scene.c_str(), "+W2000", "+H2000", "+A0.0", "+R4", o.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    bool exited = false;
    auto reaped = [&] {
        if (!exited && waitpid(pid, &status, WNOHANG) == pid) exited = true;
        return exited;
    };
    // The render has begun once the streamed PNG's temporary file exists.
    if (during_parse) std::this_thread::sleep_for(std::chrono::milliseconds(500));
    else if (!wait_until([&] { return fs::exists(tmp) || reaped(); }, 60)) return fail("no temporary file after 60 s");
    if (reaped()) return fail("lumen ended before the signal:\n" + std::string(std::istreambuf_iterator<char>(std::ifstream(log).rdbuf()), {}));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const auto sent = Clock::now();
    kill(pid, sig);
    const bool ended = wait_until(reaped, 10);
    const double elapsed = std::chrono::duration<double>(Clock::now() - sent).count();
    if (!ended) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
        return fail("lumen still running 10 s after SIG" + sig_name);
    }
    std::printf("lumen ended %.3f s after SIG%s, status %d\n", elapsed, sig_name.c_str(),
                WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status));
    int failures = 0;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 128 + sig)
        failures += fail("expected exit status " + std::to_string(128 + sig));
    if (elapsed > 1.5) failures += fail("took longer than 1.5 s to stop");
    for (const auto& entry : fs::directory_iterator(dir / "img"))
        failures += fail("left " + entry.path().filename().string() + " behind");
    return failures ? 1 : 0;
}

// Replays tests/fuzz/regressions/*: inputs that once crashed, hung or tripped a sanitizer in
// the fuzz target (tests/fuzz/parse_fuzz.cpp), and hostile inputs written by hand. Each goes
// through the same evaluation as the fuzzer (fuzz_input.hpp) and must end in a scene dump or a
// located error, quickly.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/fuzz/fuzz_input.hpp"

namespace lumen::fuzz {
namespace {

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryInputEndsInASceneOrALocatedError) {
    const fs::path dir = fs::path(LUMEN_SOURCE_DIR) / "tests" / "fuzz" / "regressions";
    size_t count = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        const auto start = std::chrono::steady_clock::now();
        const std::string out = evaluate("fuzz.pov", text.str());
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string name = entry.path().filename().string();
        EXPECT_TRUE(out.rfind("{", 0) == 0 || out.rfind("fuzz.pov:", 0) == 0) << name << ":\n" << out;
        EXPECT_LT(seconds, 5.0) << name;
        ++count;
    }
    EXPECT_GE(count, 3u);
}

}  // namespace
}  // namespace lumen::fuzz

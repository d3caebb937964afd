// Runs the tests/sdl cases: NAME.pov is interpreted from inside tests/sdl (so locations read
// "NAME.pov:line:col"), then either its dump must equal NAME.json (trailing whitespace ignored)
// or its first diagnostic line must equal the first line of NAME.err.
//   sdl_runner                      run every case (GoogleTest flags work)
//   sdl_runner --write-golden NAME  write NAME.json from the current dump (for review)
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/big_stack.hpp"
#include "interp/dump_scene.hpp"
#include "interp/interpret.hpp"
#include "base/diagnostics.hpp"
#include "parser/parser.hpp"

namespace {

namespace fs = std::filesystem;
using namespace lumen;

const fs::path kDir = LUMEN_SDL_DIR;

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Lines without trailing blanks, and no trailing empty lines.
std::vector<std::string> normalised_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        line.erase(line.find_last_not_of(" \t\r") + 1);
        lines.push_back(line);
    }
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    return line;
}

// What interpreting a case gives: the dump, or the diagnostic that stopped it.
struct Outcome {
    bool ok = false;
    std::string dump;
    std::string diagnostic;
};

Outcome interpret_case(const std::string& name) {
    Outcome out;
    const fs::path cwd = fs::current_path();
    fs::current_path(kDir);
    cli::run_with_big_stack([&] {
        SourceManager sources;  // diagnostics are formatted before the files go away
        try {
            const scene::Scene scene = interp::interpret_file(sources, name + ".pov", {});
            out.dump = interp::dump_scene_json(scene);
            out.ok = true;
        } catch (const LumenError& e) {
            out.diagnostic = format_diagnostic(e.diag);
        } catch (const std::exception& e) {
            out.diagnostic = std::string("exception: ") + e.what();
        }
    });
    fs::current_path(cwd);
    return out;
}

std::vector<std::string> case_names() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kDir))
        if (entry.path().extension() == ".pov") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

class SdlCase : public ::testing::TestWithParam<std::string> {};

TEST_P(SdlCase, MatchesGolden) {
    const std::string name = GetParam();
    const fs::path json = kDir / (name + ".json"), err = kDir / (name + ".err");
    const Outcome got = interpret_case(name);
    if (fs::exists(err)) {
        ASSERT_FALSE(got.ok) << name << ".pov should fail with: " << first_line(read_text(err));
        EXPECT_EQ(first_line(got.diagnostic), first_line(read_text(err)))
            << "full diagnostic:\n" << got.diagnostic;
    } else if (fs::exists(json)) {
        ASSERT_TRUE(got.ok) << name << ".pov failed:\n" << got.diagnostic;
        const auto want = normalised_lines(read_text(json)), have = normalised_lines(got.dump);
        for (size_t i = 0; i < std::max(want.size(), have.size()); ++i) {
            const std::string w = i < want.size() ? want[i] : "<end of file>";
            const std::string h = i < have.size() ? have[i] : "<end of dump>";
            ASSERT_EQ(h, w) << "first difference at " << name << ".json line " << i + 1
                            << "\n(tools/update-sdl-golden " << name << " rewrites it)";
        }
    } else {
        FAIL() << name << ".pov has neither " << name << ".json nor " << name << ".err";
    }
}

// Test names allow only letters, digits and '_'.
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string n = info.param;
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

INSTANTIATE_TEST_SUITE_P(Sdl, SdlCase, ::testing::ValuesIn(case_names()), test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(SdlCase);

int write_golden(const std::string& name) {
    const Outcome got = interpret_case(name);
    if (!got.ok) {
        std::cerr << got.diagnostic;
        return 1;
    }
    std::ofstream(kDir / (name + ".json"), std::ios::binary) << got.dump;
    std::cout << "wrote " << (kDir / (name + ".json")).string() << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--write-golden") {
        std::string name = argv[2];
        if (name.size() > 4 && name.compare(name.size() - 4, 4, ".pov") == 0) name.resize(name.size() - 4);
        return write_golden(fs::path(name).filename().string());
    }
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

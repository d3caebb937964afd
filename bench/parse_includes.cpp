// Parse benchmark: parses, then parses and evaluates, each of the 15 standard POV-Ray include
// files N times (default 10) and prints the mean time per include and for all of them. The
// evaluation includes colors.inc first (as scenes do), so its time is part of every figure.
//   parse_includes [N] [include folder]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "interp/interpret.hpp"
#include "base/diagnostics.hpp"
#include "parser/parser.hpp"

namespace {

using Clock = std::chrono::steady_clock;

const std::vector<std::string> kIncludes = {
    "colors.inc", "textures.inc", "metals.inc", "glass.inc",      "woods.inc",
    "stones.inc", "golds.inc",    "finish.inc", "shapes.inc",     "math.inc",
    "transforms.inc", "consts.inc", "functions.inc", "strings.inc", "skies.inc"};

template <class F>
double mean_ms(int runs, F&& f) {
    const auto start = Clock::now();
    for (int i = 0; i < runs; ++i) f();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count() / runs;
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 10;
    lumen::interp::InterpOptions options;
    if (argc > 2) options.system_include_dir = argv[2];
    std::printf("%-16s %12s %16s   (mean of %d runs)\n", "include", "parse ms", "parse+eval ms",
                runs);
    double total_parse = 0, total_eval = 0;
    int failures = 0;
    for (const std::string& inc : kIncludes) {
        lumen::SourceManager sources;
        const lumen::SourceFile* file = sources.load(options.system_include_dir + "/" + inc);
        if (!file) {
            std::printf("%-16s cannot read %s/%s\n", inc.c_str(), options.system_include_dir.c_str(),
                        inc.c_str());
            ++failures;
            continue;
        }
        // Like POV-Ray, stones.inc and skies.inc need colors.inc first; its cost is included.
        const std::string scene = "#version 3.7;\n#include \"colors.inc\"\n#include \"" + inc + "\"\n";
        // Outlives the runs: a diagnostic points into the files it holds.
        lumen::SourceManager eval_sources;
        try {
            const double parse = mean_ms(runs, [&] { lumen::parser::parse_file(*file); });
            const double eval = mean_ms(runs, [&] {
                lumen::interp::interpret_text(eval_sources, "bench.pov", scene, options);
            });
            total_parse += parse;
            total_eval += eval;
            std::printf("%-16s %12.3f %16.3f\n", inc.c_str(), parse, eval);
        } catch (const lumen::LumenError& e) {
            std::printf("%-16s failed:\n%s", inc.c_str(), lumen::format_diagnostic(e.diag).c_str());
            ++failures;
        }
    }
    const int ok = int(kIncludes.size()) - failures;
    if (ok > 0)
        std::printf("%-16s %12.3f %16.3f   (mean per include %.3f / %.3f ms)\n", "total",
                    total_parse, total_eval, total_parse / ok, total_eval / ok);
    return failures ? 1 : 0;
}

// The function VM alone: the four isosurface functions of examples/isosurface.pov, compiled as
// the interpreter compiles them and evaluated at points of their containers, one thread.
// Prints nanoseconds per evaluation (median of 5 runs) for each, so that a change to the VM or
// the noise can be judged without the noise of a whole render.
// Usage: build/bench/function_vm [EVALUATIONS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "function/vm.hpp"
#include "interp/evaluator.hpp"
#include "interp/interpret.hpp"
#include "parser/parser.hpp"

using namespace lumen;

int main(int argc, char** argv) {
    const long n = argc > 1 ? std::atol(argv[1]) : 2000000;
    const char* text =
        "#version 3.7;\n#include \"functions.inc\"\n"
        "#declare Ground = function { y + 1 - f_noise3d(x * 0.7, 0, z * 0.7) * 0.8 - f_noise3d(x * 3, 0, z * 3) * 0.1 }\n"
        "#declare Torus = function { f_torus(x, y, z, 1.1, 0.4) - f_noise3d(x * 4, y * 4, z * 4) * 0.25 }\n"
        "#declare Twist = function(x, y, z, a) { f_rounded_box(x * cos(a * y) - z * sin(a * y), y, x * sin(a * y) + z * cos(a * y), 0.15, 0.6, 1.2, 0.6) }\n"
        "#declare Twisted = function { Twist(x, y, z, 1.1) }\n"
        "#declare Blob = function { 1.1 - exp(-3 * (pow(x + 0.6, 2) + y * y + z * z)) - exp(-3 * (pow(x - 0.6, 2) + y * y + z * z))"
        " - exp(-3 * (x * x + pow(y - 0.8, 2) + z * z)) + f_noise3d(x * 5, y * 5, z * 5) * 0.15 }\n"
        "#declare Noise = function { f_noise3d(x, y, z) }\n"
        "#declare Linear = function { x * 0.7 + y - z }\n";
    SourceManager sources;
    interp::InterpOptions options;
    interp::Evaluator ev(sources, options, [](const Diagnostic&) {});
    const SourceFile* file = sources.add("bench.pov", text);
    const ast::NodePtr tree = parser::parse_file(*file);
    ev.run_main(*tree, *file, [](const interp::Item&) {});

    // Points spread over a box of half-size 2 by a fixed linear congruential sequence.
    std::vector<double> pts(3 * 4096);
    unsigned s = 12345;
    for (double& v : pts) v = ((s = s * 1103515245u + 12345u) >> 8) / double(1 << 24) * 4 - 2;

    double checksum = 0;
    for (const char* name : {"Ground", "Torus", "Twisted", "Blob", "Noise", "Linear"}) {
        const auto& f = *std::get<std::shared_ptr<const interp::FunctionValue>>(ev.symbols.find(name)->v);
        std::vector<double> times;
        for (int rep = 0; rep < 5; ++rep) {
            const auto t0 = std::chrono::steady_clock::now();
            for (long i = 0; i < n; ++i)
                checksum += fn::evaluate(*f.program, std::span(pts.data() + 3 * (i & 4095), 3));
            times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        std::sort(times.begin(), times.end());
        std::printf("%-8s %6.1f ns/evaluation\n", name, times[2] / n * 1e9);
    }
    std::printf("checksum %.17g\n", checksum);
}

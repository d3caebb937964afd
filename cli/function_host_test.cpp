// Pigment, pattern and transform functions called while parsing, evaluated by the renderer's
// host (render/function_host.cpp), against POV-Ray 3.7.0.10: the expected lines are what
// povray printed for the same scene with #debug (2026-12-05).
#include "interp/eval_test_support.hpp"
#include "render/function_host.hpp"

namespace lumen::cli {
namespace {

using FunctionHost = interp::testing::EvalTest;

const char* const kScene = R"(#version 3.7;
#include "functions.inc"
#declare P = function { pigment { gradient x color_map { [0 rgb <0.3, 0.2, 0.1>] [1 rgb <0.9, 0.5, 1>] } } }
#declare T = function { transform { rotate 90*z translate x scale 2 } }
#declare PA = function { pattern { bozo scale 0.3 } }
#declare G = function { P(x, y, z).gray + T(x, y, z).y + PA(x, y, z) }
#debug concat(str(P(0.25, 0, 0).red, 0, 17), " ", str(P(0.25, 0, 0).blue, 0, 17), "\n")
#debug concat(str(T(1, 0, 0).x, 0, 17), " ", str(T(1, 0, 0).y, 0, 17), "\n")
#debug concat(str(PA(0.1, 0.2, 0.3), 0, 17), "\n")
#debug concat(str(G(0.1, 0.2, 0.3), 0, 17), "\n")
#debug concat(str(f_granite(0.1, 0.2, 0.3), 0, 17), " ", str(f_wood(0.5, 0.2, 0.3), 0, 17), "\n")
#debug concat(str(f_hexagon(0.1, 0.2, 0.3).gray, 0, 17), "\n")
)";

const char* const kPovRay = R"(0.44999998807907104 0.32499998807907104
2.00000000000000000 2.00000000000000000
0.65212957287094397
1.11617957930526535
0.64365354575611045 0.92296703857309903
0.00000000000000000
)";

TEST_F(FunctionHost, PigmentPatternAndTransformFunctionsMatchPovRay) {
    options.function_host = render::shared_function_host();
    run(kScene);
    EXPECT_EQ(debug_output(), kPovRay);
}

// The host keeps the last colour it made, per thread, for the channels asked one by one at
// the same point: another pigment, or another point, is a new colour.
TEST_F(FunctionHost, ChannelsAskedInTurnComeFromTheirOwnPigmentAndPoint) {
    options.function_host = render::shared_function_host();
    run(R"(#version 3.7;
#declare P = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] } } }
#declare Q = function { pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } } }
#debug concat(str(P(0.5, 0.25, 0).red, 0, 4), " ", str(Q(0.5, 0.25, 0).red, 0, 4), " ",
              str(P(0.5, 0.25, 0).green, 0, 4), " ", str(P(0.25, 0.5, 0).blue, 0, 4), " ",
              str(Q(0.5, 0.75, 0).green, 0, 4), "\n")
)");
    EXPECT_EQ(debug_output(), "0.5000 0.2500 0.2500 0.0625 0.7500\n");
}

}  // namespace
}  // namespace lumen::cli

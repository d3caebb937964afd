// Splines (function/spline.cpp): the four types, a float spline, a copy retyped and extended
// (a repeated t replaces a value, except at the largest t) and a spline function, against
// what POV-Ray 3.7.0.10 printed for the same scene with #debug (2026-12-05).
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "base/source.hpp"
#include "interp/interpret.hpp"

namespace lumen::interp {
namespace {

const char* const kScene = R"(#version 3.7;
#declare S = spline { linear_spline 0, <0,0,0>, 1, <1,2,0>, 2.5, <3,1,1>, 4, <2,-1,3>, 5, <0,0,0> }
#declare F = spline { 0, 1, 1, 3, 3, -2, 4, 5 }
#macro P(V) #debug concat(vstr(3, V, " ", 0, 12), "\n") #end
#for (T, -0.5, 5.5, 0.7)
  P(S(T)) P(S(T, quadratic_spline)) P(S(T, cubic_spline)) P(S(T, natural_spline))
  #debug concat(str(F(T).x, 0, 12), " ", str(F(T, natural_spline).y, 0, 12), "\n")
#end
#declare S2 = spline { S natural_spline 6, <1,1,1> 2.5, <9,9,9> 6, <7,7,7> }
P(S2(5.5)) P(S2(2.5)) P(S2(3))
#declare Fn = function { spline { S2 } }
#debug concat(str(Fn(5.5).x, 0, 12), " ", str(Fn(3).z, 0, 12), "\n")
)";

const char* const kPovRay = R"(0.000000000000 0.000000000000 0.000000000000
0.000000000000 0.000000000000 0.000000000000
1.000000000000 2.000000000000 0.000000000000
0.000000000000 0.000000000000 0.000000000000
1.000000000000 1.000000000000
0.200000000000 0.400000000000 0.000000000000
0.178666666667 0.570666666667 -0.042666666667
1.000000000000 2.000000000000 0.000000000000
0.168000000000 0.496000000000 -0.005647058824
1.400000000000 1.676000000000
0.900000000000 1.800000000000 0.000000000000
0.888000000000 1.896000000000 -0.024000000000
1.000000000000 2.000000000000 0.000000000000
0.871500000000 1.885500000000 -0.005029411765
2.800000000000 3.045812500000
1.800000000000 1.600000000000 0.400000000000
1.728000000000 2.176000000000 0.256000000000
1.908000000000 1.936000000000 0.280000000000
1.908000000000 2.116000000000 0.112705882353
1.500000000000 1.300500000000
2.733333333333 1.133333333333 0.866666666667
2.698666666667 1.410666666667 0.797333333333
2.879703703704 1.214222222222 0.808888888889
2.846000000000 1.334592592593 0.689877995643
-0.250000000000 -1.580875000000
2.666666666667 0.333333333333 1.666666666667
3.000000000000 0.444444444444 1.555555555556
2.962962962963 0.277777777778 1.833333333333
3.055555555556 0.092592592593 2.025054466231
-2.000000000000 -2.000000000000
2.200000000000 -0.600000000000 2.600000000000
2.440000000000 -0.520000000000 2.520000000000
2.376000000000 -0.808000000000 3.000000000000
2.452000000000 -0.876000000000 3.079294117647
2.900000000000 2.336937500000
1.200000000000 -0.600000000000 1.800000000000
1.328000000000 -0.824000000000 2.216000000000
2.000000000000 -1.000000000000 3.000000000000
1.264000000000 -0.792000000000 2.172705882353
5.000000000000 5.000000000000
0.000000000000 0.000000000000 0.000000000000
0.000000000000 0.000000000000 0.000000000000
2.000000000000 -1.000000000000 3.000000000000
0.000000000000 0.000000000000 0.000000000000
5.000000000000 5.000000000000
0.326010886470 0.736197511664 0.193818040435
9.000000000000 9.000000000000 9.000000000000
7.858303093140 6.376303208341 8.447727665457
0.326010886470 8.447727665457
)";

TEST(Splines, FourTypesCopiesAndFunctionsMatchPovRay) {
    SourceManager sources;
    std::string printed;
    interpret_text(sources, "splines.pov", kScene, InterpOptions{},
                   [&](const Diagnostic& d) { printed += d.message; });  // #debug text
    EXPECT_EQ(printed, kPovRay);
}

TEST(Splines, CallErrorsAreLocated) {
    SourceManager sources;
    auto error = [&](const std::string& text) {
        try {
            interpret_text(sources, "t.pov", text, InterpOptions{});
        } catch (const LumenError& e) {
            return std::to_string(e.diag.loc.line) + ":" + std::to_string(e.diag.loc.column) + ": " +
                   e.what();
        }
        return std::string();
    };
    EXPECT_EQ(error("#declare S = spline { }"), "1:14: a spline needs at least one entry");
    EXPECT_EQ(error("#declare S = spline { 0, 1 }\n#declare V = S(0, 1);"),
              "2:19: expected linear_spline, quadratic_spline, cubic_spline or natural_spline");
}

}  // namespace
}  // namespace lumen::interp

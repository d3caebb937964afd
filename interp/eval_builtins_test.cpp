// Built-in functions. Expected values come from POV-Ray 3.7 (#debug of str()/vstr()).
#include <filesystem>
#include <fstream>

#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuiltinTest = EvalTest;
using V = std::vector<double>;

void expect_vec_near(const std::vector<double>& got, const V& want, double tol = 1e-6) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
}

TEST_F(BuiltinTest, MathFunctions) {
    EXPECT_DOUBLE_EQ(number("abs(-3)"), 3);
    EXPECT_DOUBLE_EQ(number("sqrt(16)"), 4);
    EXPECT_NEAR(number("exp(1)"), 2.718282, 1e-6);
    EXPECT_NEAR(number("ln(10)"), 2.302585, 1e-6);
    EXPECT_DOUBLE_EQ(number("log(100)"), 2);
    EXPECT_NEAR(number("pow(2,0.5)"), 1.414214, 1e-6);
    EXPECT_NEAR(number("degrees(pi)"), 180, 1e-12);
    EXPECT_NEAR(number("radians(180)"), 3.141593, 1e-6);
    EXPECT_NEAR(number("atan2(1,-1)"), 2.356194, 1e-6);
    EXPECT_NEAR(number("sin(pi/2) + cos(0) + tan(0)"), 2, 1e-12);
    EXPECT_NEAR(number("asin(1) + acos(1) + atan(0)"), 1.570796, 1e-6);
    EXPECT_NEAR(number("asinh(1)"), 0.881374, 1e-6);
    EXPECT_NEAR(number("acosh(2)"), 1.316958, 1e-6);
    EXPECT_NEAR(number("atanh(0.5)"), 0.549306, 1e-6);
    EXPECT_NEAR(number("sinh(1)"), 1.175201, 1e-6);
    EXPECT_NEAR(number("cosh(1)"), 1.543081, 1e-6);
    EXPECT_NEAR(number("tanh(1)"), 0.761594, 1e-6);
}

TEST_F(BuiltinTest, RoundingFunctionsMatchPov) {
    EXPECT_DOUBLE_EQ(number("mod(-7,3)"), -1);
    EXPECT_DOUBLE_EQ(number("div(-7,2)"), -3);
    EXPECT_DOUBLE_EQ(number("int(-2.5)"), -2);
    EXPECT_DOUBLE_EQ(number("floor(-2.5)"), -3);
    EXPECT_DOUBLE_EQ(number("ceil(-2.5)"), -2);
    EXPECT_DOUBLE_EQ(number("int(7/2)"), 3);
}

TEST_F(BuiltinTest, MinMaxSelectBitwise) {
    EXPECT_DOUBLE_EQ(number("min(3,1,2)"), 1);
    EXPECT_DOUBLE_EQ(number("max(3,1,2)"), 3);
    EXPECT_DOUBLE_EQ(number("select(-1,1,2,3)"), 1);
    EXPECT_DOUBLE_EQ(number("select(0,1,2,3)"), 2);
    EXPECT_DOUBLE_EQ(number("select(1,1,2,3)"), 3);
    EXPECT_DOUBLE_EQ(number("select(0,1,2)"), 2);
    EXPECT_DOUBLE_EQ(number("select(-0.5,1,2)"), 1);
    EXPECT_DOUBLE_EQ(number("bitwise_and(12,10)"), 8);
    EXPECT_DOUBLE_EQ(number("bitwise_or(12,10)"), 14);
    EXPECT_DOUBLE_EQ(number("bitwise_xor(12,10)"), 6);
}

TEST_F(BuiltinTest, SumAndProduct) {
    EXPECT_DOUBLE_EQ(number("sum(I, 1, 4, I*I)"), 30);
    EXPECT_DOUBLE_EQ(number("prod(I, 1, 4, I)"), 24);
}

TEST_F(BuiltinTest, RandomStreamsMatchPovRay) {
    run("#declare S = seed(42);\n"
        "#declare A = rand(S); #declare B = rand(S); #declare C = rand(S);\n"
        "#declare S2 = seed(0); #declare D = rand(S2);\n"
        "#declare S3 = seed(-5); #declare E = rand(S3);\n"
        "#declare S4 = seed(123456789); #declare F = rand(S4);\n");
    EXPECT_NEAR(num_var("A"), 0.723583, 1e-6);
    EXPECT_NEAR(num_var("B"), 0.329979, 1e-6);
    EXPECT_NEAR(num_var("C"), 0.755762, 1e-6);
    EXPECT_NEAR(num_var("D"), 0.000003, 1e-6);
    EXPECT_NEAR(num_var("E"), 0.890053, 1e-6);
    EXPECT_NEAR(num_var("F"), 0.498219878063123, 1e-14);
    EXPECT_EQ(expr_error("rand(99)"), "expr:1:6: error: rand() needs a stream made by seed()");
}

TEST_F(BuiltinTest, VturbulenceMatchesPovRay) {
    // povray printed these with vstr(3, vturbulence(2.1, 0.45, Octaves, P), " ", 0, 9).
    struct Case { const char* call; std::vector<double> want; };
    const Case cases[] = {
        {"vturbulence(2.1, 0.45, 6, <0.3, 1.7, -2.2>)", {0.062854203, 0.236673297, 0.318124176}},
        {"vturbulence(2.1, 0.45, 1, <10.5, 0, 3.25>)", {-0.355312327, -0.222720453, 0.079218689}},
        {"vturbulence(2.1, 0.45, 3.7, <-4.1, 2.9, 0.6>)", {-0.129189474, -0.364321248, -0.308491371}},
        {"vturbulence(2.1, 0.45, 20, <0, 0, 0>)", {-0.805942733, 0.656150123, -0.835562643}},
    };
    for (const Case& c : cases) {
        const std::vector<double> got = components(value(c.call));
        ASSERT_EQ(got.size(), 3u);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], c.want[i], 1e-9) << c.call;
    }
}

TEST_F(BuiltinTest, VectorFunctions) {
    EXPECT_DOUBLE_EQ(number("vdot(<1,2,3>,<4,5,6>)"), 32);
    EXPECT_EQ(vec("vcross(<1,0,0>,<0,1,0>)"), (V{0, 0, 1}));
    expect_vec_near(vec("vnormalize(<3,0,4>)"), {0.6, 0, 0.8}, 1e-15);
    EXPECT_DOUBLE_EQ(number("vlength(<3,4,0>)"), 5);
    EXPECT_DOUBLE_EQ(number("vlength(1)"), std::sqrt(3.0));  // a float is <1, 1, 1> (POV)
    expect_vec_near(vec("vrotate(<0,1,0>,<90,0,0>)"), {0, 0, 1}, 1e-12);
    expect_vec_near(vec("vrotate(<1,0,0>,<0,90,0>)"), {0, 0, -1}, 1e-12);
    expect_vec_near(vec("vrotate(<1,0,0>,<0,0,90>)"), {0, 1, 0}, 1e-12);
    expect_vec_near(vec("vrotate(<1,2,3>,<10,20,30>)"), {1.067425, 2.289059, 2.760581});
    expect_vec_near(vec("vaxis_rotate(<1,0,0>,<0,1,0>,90)"), {0, 0, -1}, 1e-12);
    expect_vec_near(vec("vaxis_rotate(<1,2,3>,<1,1,0>,33)"), {2.236019, 0.763981, 2.901130});
}

TEST_F(BuiltinTest, StringFunctions) {
    EXPECT_EQ(str("substr(\"abcdef\",2,3)"), "bcd");
    EXPECT_EQ(str("strupr(\"aBc\")"), "ABC");
    EXPECT_EQ(str("strlwr(\"aBc\")"), "abc");
    EXPECT_EQ(str("chr(66)"), "B");
    EXPECT_EQ(str("concat(\"a\", \"bc\", chr(100))"), "abcd");
    EXPECT_DOUBLE_EQ(number("asc(\"A\")"), 65);
    EXPECT_DOUBLE_EQ(number("strlen(\"hello\")"), 5);
    EXPECT_DOUBLE_EQ(number("strcmp(\"abc\",\"abd\")"), -1);
    EXPECT_DOUBLE_EQ(number("strcmp(\"b\",\"a\")"), 1);
    EXPECT_DOUBLE_EQ(number("strcmp(\"x\",\"x\")"), 0);
    EXPECT_DOUBLE_EQ(number("val(\"3.5e2xyz\")"), 350);
    EXPECT_DOUBLE_EQ(number("val(\"  12\")"), 12);
    EXPECT_EQ(expr_error("substr(\"abc\",2,3)"),
              "expr:1:1: error: substr() range is outside the string (length 3)");
}

TEST_F(BuiltinTest, StrAndVstrFormatLikePrintf) {
    EXPECT_EQ(str("str(1/3,0,6)"), "0.333333");
    EXPECT_EQ(str("str(2.5,5,2)"), " 2.50");
    EXPECT_EQ(str("str(-3,-4,1)"), "-3.0");
    EXPECT_EQ(str("str(1.23456,-8,2)"), "00001.23");
    EXPECT_EQ(str("str(-1.5,6,1)"), "  -1.5");
    EXPECT_EQ(str("str(12,3,0)"), " 12");
    EXPECT_EQ(str("str(1/3,0,20)"), "0.33333333333333331483");  // no cap at 16 digits (POV)
    EXPECT_EQ(str("str(3.14159,0,-1)"), "3.141590");
    EXPECT_EQ(str("str(2.5,0,0)"), "2");
    EXPECT_EQ(str("str(1e20,0,-1)"), "100000000000000000000.000000");
    EXPECT_EQ(str("vstr(3,<1,2,3>,\",\",0,1)"), "1.0,2.0,3.0");
    EXPECT_EQ(str("vstr(2,<1,2>,\", \",3,2)"), "1.00, 2.00");
    EXPECT_EQ(str("vstr(5,<1,2,3>,\"/\",0,0)"), "1/2/3/0/0");
}

TEST_F(BuiltinTest, ArrayFunctionsAndDefined) {
    run("#declare Arr = array[2][3];");
    EXPECT_DOUBLE_EQ(number("dimensions(Arr)"), 2);
    EXPECT_DOUBLE_EQ(number("dimension_size(Arr,2)"), 3);
    EXPECT_DOUBLE_EQ(number("defined(Arr)"), 1);
    EXPECT_DOUBLE_EQ(number("defined(Nope)"), 0);
    EXPECT_DOUBLE_EQ(number("defined(Arr[0][0])"), 0);
    EXPECT_EQ(expr_error("dimension_size(Arr,3)"), "expr:1:20: error: the array has no dimension 3");
}

TEST_F(BuiltinTest, FileExistsSearchesIncludePaths) {
    auto dir = std::filesystem::temp_directory_path() / "lumen_fe_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "here.inc") << "// x\n";
    options.library_paths = {dir.string()};
    EXPECT_DOUBLE_EQ(number("file_exists(\"here.inc\")"), 1);
    EXPECT_DOUBLE_EQ(number("file_exists(\"nope.inc\")"), 0);
    std::filesystem::remove_all(dir);
}

TEST_F(BuiltinTest, ArgumentErrors) {
    EXPECT_EQ(expr_error("sqrt(1, 2)"), "expr:1:1: error: 'sqrt' takes 1 argument(s), found 2");
    EXPECT_EQ(expr_error("min()"), "expr:1:1: error: 'min' takes at least 1 argument(s), found 0");
    EXPECT_EQ(expr_error("strlen(5)"), "expr:1:8: error: expected a string, found a float");
    EXPECT_EQ(expr_error("vdot(\"a\", x)"), "expr:1:6: error: expected a vector, found a string");
    EXPECT_EQ(expr_error("min_extent(x)"), "expr:1:12: error: expected an object, found a vector");
    EXPECT_EQ(expr_error("trace(x, x, x)"), "expr:1:7: error: expected an object, found a vector");
    EXPECT_EQ(expr_error("sqr(2)"), "expr:1:1: error: undeclared identifier 'sqr'");
}

TEST_F(BuiltinTest, MisspeltFunctionGetsAHint) {
    try {
        value("vnormalise(x)");
        FAIL() << "expected an error";
    } catch (const LumenError& e) {
        EXPECT_EQ(e.diag.hint, "did you mean 'vnormalize'?");
    }
}

}  // namespace
}  // namespace lumen::interp::testing

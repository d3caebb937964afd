// julia_fractal { <c> [algebra] [function] [max_iteration N] [precision P] [slice <n>, d]
// modifiers }: as POV-Ray reads it, the fractal's own keywords in any order before the object
// modifiers, with its checks: a slice of length under 1e-5 or with |t| < 1e-10 (before it is
// normalised) is an error, quaternions take only sqr and cube (checked once the block is read,
// so `sin quaternion` fails too), precision under 1 counts as 1 and max_iteration is
// truncated (0 or less: every point is inside, nothing is drawn).
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

using scene::JuliaFunction;

// The most iterations lumen runs per point: each march step costs as many, and the
// normal's orbit is kept per ray.
constexpr int kMaxJuliaIterations = 4096;

constexpr std::pair<const char*, JuliaFunction> kFunctionWords[] = {
    {"sqr", JuliaFunction::Sqr},     {"cube", JuliaFunction::Cube},
    {"exp", JuliaFunction::Exp},     {"reciprocal", JuliaFunction::Reciprocal},
    {"sin", JuliaFunction::Sin},     {"asin", JuliaFunction::Asin},
    {"sinh", JuliaFunction::Sinh},   {"asinh", JuliaFunction::Asinh},
    {"cos", JuliaFunction::Cos},     {"acos", JuliaFunction::Acos},
    {"cosh", JuliaFunction::Cosh},   {"acosh", JuliaFunction::Acosh},
    {"tan", JuliaFunction::Tan},     {"atan", JuliaFunction::Atan},
    {"tanh", JuliaFunction::Tanh},   {"atanh", JuliaFunction::Atanh},
    {"ln", JuliaFunction::Ln},       {"pwr", JuliaFunction::Pwr}};

// A 4-D vector: a float fills all four components, shorter vectors get zeros.
std::array<double, 4> read_vector4(ItemCursor& cur, const char* after) {
    const SourceLoc loc = cur.next_loc();
    const std::vector<double> v = cur.expect_vecn(after);
    if (v.size() > 4) cur.fail(loc, "julia_fractal needs a 4-D vector here");
    if (v.size() == 1) return {v[0], v[0], v[0], v[0]};
    std::array<double, 4> out{0, 0, 0, 0};
    for (size_t i = 0; i < v.size(); ++i) out[i] = v[i];
    return out;
}

void read_slice(ItemCursor& cur, SourceLoc loc, scene::JuliaFractal& j) {
    std::array<double, 4> n = read_vector4(cur, "slice");
    j.slice_distance = cur.expect_float("slice");
    const double len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3];
    if (!(len2 >= 1e-10)) cur.fail(loc, "julia_fractal slice vector is zero");
    if (!(std::fabs(n[3]) >= 1e-10))
        cur.fail(loc, "julia_fractal slice t component is zero (w would be undefined)");
    const double inv = 1 / std::sqrt(len2);
    for (double& c : n) c *= inv;
    j.slice = n;
}

// One of the fractal's own keywords, if the next item is one.
bool read_fractal_keyword(ItemCursor& cur, scene::JuliaFractal& j, SourceLoc& function_loc) {
    if (cur.at_end() || cur.peek().kind != Item::Kind::Keyword) return false;
    const std::string word = cur.peek().keyword;
    const SourceLoc loc = cur.peek().loc;
    if (word == "quaternion" || word == "hypercomplex") {
        cur.next();
        j.algebra = word == "quaternion" ? scene::JuliaAlgebra::Quaternion
                                         : scene::JuliaAlgebra::Hypercomplex;
        return true;
    }
    if (word == "max_iteration") {
        cur.next();
        const double n = cur.expect_float("max_iteration");
        if (n > kMaxJuliaIterations) {
            cur.warn(loc, "max_iteration " + std::to_string(n) + " is more than lumen runs; using " +
                              std::to_string(kMaxJuliaIterations));
            j.max_iteration = kMaxJuliaIterations;
        } else {
            j.max_iteration = n > -1 ? int(n) : 0;  // POV-Ray truncates; <= 0 draws nothing
        }
        return true;
    }
    if (word == "precision") {
        cur.next();
        const double p = cur.expect_float("precision");
        j.precision = p < 1 || !std::isfinite(p) ? 1 : p;
        return true;
    }
    if (word == "slice") {
        cur.next();
        read_slice(cur, loc, j);
        return true;
    }
    for (const auto& [name, fn] : kFunctionWords) {
        if (word != name) continue;
        cur.next();
        j.function = fn;
        function_loc = loc;
        if (fn == JuliaFunction::Pwr) {
            if (!cur.next_is<VecN>()) cur.fail(loc, "pwr needs its exponent: pwr(a, b)");
            const std::vector<double> e = cur.expect_vecn("pwr");
            j.exponent = {e[0], e.size() > 1 ? e[1] : 0.0};
        }
        return true;
    }
    return false;
}

}  // namespace

scene::ObjectPtr build_julia_fractal(ItemCursor& cur) {
    scene::JuliaFractal j;
    j.c = read_vector4(cur, "");
    SourceLoc function_loc = cur.block_loc();
    while (read_fractal_keyword(cur, j, function_loc)) {
    }
    if (j.algebra == scene::JuliaAlgebra::Quaternion && j.function != JuliaFunction::Sqr &&
        j.function != JuliaFunction::Cube)
        cur.fail(function_loc, "illegal function: quaternion only supports sqr and cube");
    scene::Object obj;
    obj.loc = cur.block_loc();
    obj.shape = j;
    read_object_modifiers(cur, obj, [](const Item&) { return false; }, {});
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace lumen::interp

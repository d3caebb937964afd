// parametric { function { FX } [,] function { FY } [,] function { FZ } <u1, v1>, <u2, v2>
// [contained_by { box { C1, C2 } | sphere { C, R } }] [accuracy A] [max_gradient G]
// [precompute Depth [, x] [, y] [, z]] OBJECT_MODIFIERS }, read as POV-Ray 3.7 reads it: the
// functions take u and v in their first two parameters, the uv corners are sorted, the box
// -1 to 1 is the default container, accuracy and max_gradient at or below 0 are warned about
// and set back to their defaults (0.001 and 1), and a depth outside 1..20 is POV-Ray's
// "Precompute: invalid depth" error.
#include <algorithm>
#include <cmath>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

fn::ProgramPtr read_function(ItemCursor& cur, const char* axis) {
    const SourceLoc loc = cur.next_loc();
    if (!cur.next_is<std::shared_ptr<const FunctionValue>>())
        cur.fail(loc, std::string("a parametric needs three functions: ") + axis +
                          " is missing (function { ... })");
    const FunctionValue& f = *cur.next().value.as<std::shared_ptr<const FunctionValue>>();
    if (!f.program) cur.fail(loc, "a parametric's functions are float functions, not a " + f.keyword);
    if (f.program->params < 2 || f.program->params > 3 || f.program->components != 1)
        cur.fail(loc, "a parametric's function takes u and v (or x, y and z), not " +
                          std::to_string(f.program->params) + " parameters");
    return f.program;
}

// `precompute Depth, x, y, z`: the depth, then any of the axes, in that order.
void read_precompute(ItemCursor& cur, const Item& kw, scene::Parametric& p) {
    const SourceLoc at = cur.next_loc();
    const double depth = cur.expect_float(kw.keyword);
    if (!(depth >= 1 && depth <= 20)) cur.fail(at, "Precompute: invalid depth (1 to 20)");
    p.precompute_depth = int(depth);
    int last = -1;
    while (!cur.at_end() && cur.next_is_vector_like() && !cur.next_is_float()) {
        const SourceLoc loc = cur.next_loc();
        const std::vector<double> v = cur.expect_vecn(kw.keyword);
        int named = -1;
        for (int k = 0; k < 3; ++k)
            if (v.size() == 3 && v[k] == 1 && v[(k + 1) % 3] == 0 && v[(k + 2) % 3] == 0) named = k;
        if (named <= last) cur.fail(loc, "precompute takes x, y and z, in that order");
        p.precompute[named] = true;
        last = named;
    }
}

}  // namespace

scene::ObjectPtr build_parametric(ItemCursor& cur) {
    scene::Parametric p;
    p.functions = {read_function(cur, "x"), read_function(cur, "y"), read_function(cur, "z")};
    const glm::dvec2 a = read_vector2(cur, "the parametric's first uv corner");
    const glm::dvec2 b = read_vector2(cur, "the parametric's second uv corner");
    p.uv_lo = glm::min(a, b);
    p.uv_hi = glm::max(a, b);
    p.globals = cur.ctx().pattern_globals;
    static const std::vector<std::string> kWords = {"contained_by", "accuracy", "max_gradient",
                                                    "precompute"};
    auto extra = [&](const Item& item) {
        if (const BlockValue* block = block_of(item, "contained_by")) {
            read_container(cur, *block, p.container);
            return true;
        }
        if (item.kind != Item::Kind::Keyword) return false;
        const std::string& w = item.keyword;
        if (w == "accuracy") {
            p.accuracy = positive_or_default(cur, item, 0.001, "parametric");
        } else if (w == "max_gradient") {
            p.max_gradient = positive_or_default(cur, item, 1, "parametric");
        } else if (w == "precompute") {
            read_precompute(cur, item, p);
        } else {
            return false;
        }
        return true;
    };
    return contained_object(cur, p, extra, kWords, "parametric");
}

}  // namespace lumen::interp

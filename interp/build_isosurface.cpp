// isosurface { function { F } [contained_by { box { C1, C2 } | sphere { C, R } }] [threshold T]
// [accuracy A] [max_gradient G] [evaluate P0, P1, P2] [open] [max_trace N] [all_intersections]
// OBJECT_MODIFIERS }, read as POV-Ray 3.7 reads it: the function first, a box container by
// default (-1 to 1), box corners sorted, accuracy and max_gradient at or below 0 warned about
// and set back to their defaults, max_trace kept within 1..10.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "interp/build_common.hpp"

namespace lumen::interp {

// contained_by { box { C1, C2 } } or { sphere { C, R } }: a plain box or sphere, untransformed.
void read_container(ItemCursor& cur, const BlockValue& block, scene::Container& c) {
    ItemCursor sub(cur.ctx(), block);
    const SourceLoc loc = sub.next_loc();
    const scene::ObjectPtr& o = sub.expect<scene::ObjectPtr>("contained_by", "a box or a sphere");
    if (!o->transform.is_identity())
        cur.fail(loc, "a contained_by box or sphere cannot be transformed: transform the shape");
    if (const auto* b = std::get_if<scene::Box>(&o->shape)) {
        c.sphere = false;
        c.lo = glm::min(b->min, b->max);
        c.hi = glm::max(b->min, b->max);
    } else if (const auto* s = std::get_if<scene::Sphere>(&o->shape)) {
        c.sphere = true;
        c.center = s->center;
        c.radius = s->radius;
    } else {
        cur.fail(loc, "contained_by takes a box or a sphere");
    }
    if (!sub.at_end()) sub.fail_expected("the end of contained_by", "");
}

double positive_or_default(ItemCursor& cur, const Item& kw, double fallback, const char* shape) {
    const double v = cur.expect_float(kw.keyword);
    if (v > 0) return v;
    char text[32];
    std::snprintf(text, sizeof text, "%g", fallback);
    cur.warn(kw.loc, std::string("a") + (shape[0] == 'i' ? "n " : " ") + shape + "'s " +
                         kw.keyword + " must be above 0: using " + text);
    return fallback;
}

scene::ObjectPtr build_isosurface(ItemCursor& cur) {
    const SourceLoc loc = cur.next_loc();
    if (!cur.next_is<std::shared_ptr<const FunctionValue>>())
        cur.fail(loc, "an isosurface starts with its function { ... }");
    const FunctionValue& f = *cur.next().value.as<std::shared_ptr<const FunctionValue>>();
    if (!f.program) return unsupported_object({"isosurface of a " + f.keyword, loc});  // a spline
    if (f.program->params != 3)
        cur.fail(loc, "an isosurface's function takes x, y and z, not " +
                          std::to_string(f.program->params) + " parameters");
    scene::Isosurface iso;
    iso.function = f.program;
    iso.globals = cur.ctx().pattern_globals;
    static const std::vector<std::string> kWords = {
        "contained_by", "threshold", "accuracy", "max_gradient", "evaluate", "open",
        "max_trace", "all_intersections"};
    auto extra = [&](const Item& item) {
        if (const BlockValue* b = block_of(item, "contained_by")) {
            read_container(cur, *b, iso.container);
            return true;
        }
        if (item.kind != Item::Kind::Keyword) return false;
        const std::string& w = item.keyword;
        if (w == "threshold") {
            iso.threshold = cur.expect_float(w);
        } else if (w == "accuracy") {
            iso.accuracy = positive_or_default(cur, item, 0.001, "isosurface");
        } else if (w == "max_gradient") {
            iso.max_gradient = positive_or_default(cur, item, 1.1, "isosurface");
        } else if (w == "evaluate") {
            glm::dvec3 e;
            for (int i = 0; i < 3; ++i) e[i] = cur.expect_float(w);
            iso.evaluate = e;
        } else if (w == "open") {
            iso.open = cur.optional_bool();
        } else if (w == "max_trace") {
            const SourceLoc at = cur.next_loc();
            const double n = cur.expect_float(w);
            if (n < 1 || n > 10) cur.warn(at, "an isosurface's max_trace is kept within 1 to 10");
            iso.max_trace = int(std::clamp(std::isnan(n) ? 1.0 : n, 1.0, 10.0));
        } else if (w == "all_intersections") {
            iso.max_trace = 10;
        } else {
            return false;
        }
        return true;
    };
    return contained_object(cur, iso, extra, kWords, "isosurface");
}

}  // namespace lumen::interp

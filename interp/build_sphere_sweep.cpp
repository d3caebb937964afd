// sphere_sweep { linear_spline | b_spline | cubic_spline N, <C>, R, ... [tolerance T]
// OBJECT_MODIFIERS }, read as POV-Ray 3.7 reads it (probed with povray): the spline keyword
// first and only once ("Invalid type of interpolation" otherwise), N truncated, at least two
// spheres for linear_spline and four for the others ("Too few modeling spheres for
// interpolation type", reported at the count), commas optional, a float centre promoted to a
// vector, any radius taken (negative and zero too), tolerance only before the modifiers.
#include <cmath>
#include <string>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// POV-Ray bounds nothing here; lumen does, so a runaway count is a located error.
constexpr int kMaxSpheres = 1'000'000;

bool accept_sweep_spline(ItemCursor& cur, scene::SweepSpline& kind) {
    static const std::pair<const char*, scene::SweepSpline> kWords[] = {
        {"linear_spline", scene::SweepSpline::Linear},
        {"b_spline", scene::SweepSpline::BSpline},
        {"cubic_spline", scene::SweepSpline::Cubic}};
    for (const auto& [word, k] : kWords)
        if (cur.accept_keyword(word)) {
            kind = k;
            return true;
        }
    return false;
}

double finite_float(ItemCursor& cur, const char* what) {
    const SourceLoc loc = cur.next_loc();
    const double v = cur.expect_float("");
    if (!std::isfinite(v)) cur.fail(loc, std::string("a sphere_sweep's ") + what + " is not finite");
    return v;
}

}  // namespace

scene::ObjectPtr build_sphere_sweep(ItemCursor& cur) {
    scene::SphereSweep sweep;
    if (!accept_sweep_spline(cur, sweep.spline))
        cur.fail(cur.next_loc(), "a sphere_sweep starts with its interpolation type: "
                                 "linear_spline, b_spline or cubic_spline");
    const SourceLoc count_loc = cur.next_loc();
    const int n = cur.expect_int("");
    const int fewest = sweep.spline == scene::SweepSpline::Linear ? 2 : 4;
    if (n < fewest)
        cur.fail(count_loc, std::string("too few spheres for a sphere_sweep's ") +
                                (fewest == 2 ? "linear_spline: it needs at least two"
                                             : "b_spline or cubic_spline: it needs at least four"));
    if (n > kMaxSpheres)
        cur.fail(count_loc, "a sphere_sweep has more than " + std::to_string(kMaxSpheres) +
                                " spheres");
    sweep.spheres.reserve(size_t(n));
    for (int i = 0; i < n; ++i) {
        const SourceLoc loc = cur.next_loc();
        scene::Sphere s;
        s.center = cur.expect_vector("");
        if (!std::isfinite(s.center.x + s.center.y + s.center.z))
            cur.fail(loc, "a sphere_sweep's centre is not finite");
        s.radius = finite_float(cur, "radius");
        sweep.spheres.push_back(s);
    }
    if (cur.accept_keyword("tolerance")) sweep.tolerance = finite_float(cur, "tolerance");
    scene::Object obj;
    obj.loc = cur.block_loc();
    read_object_modifiers(cur, obj, [&](const Item& item) {
        if (item.kind == Item::Kind::Keyword && item.keyword == "tolerance")
            cur.fail(item.loc, "a sphere_sweep's tolerance comes before its object modifiers "
                               "(and only once)");
        return false;
    }, {"tolerance"});
    obj.shape = std::move(sweep);
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace lumen::interp

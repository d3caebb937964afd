// prism, lathe and sor: a spline kind and sweep, the point count and the points, then the
// modifiers with the shapes' own flags (open, sturm). Point lists POV-Ray rejects are located
// errors with its reasons (too few points for the spline, an outline that does not close, a
// surface of revolution whose heights do not rise).
#include <string>
#include <vector>

#include "interp/build_common.hpp"
#include "scene/spline_segments.hpp"

namespace lumen::interp {

namespace {

const char* spline_name(scene::SplineKind k) {
    switch (k) {
        case scene::SplineKind::Linear: return "linear";
        case scene::SplineKind::Quadratic: return "quadratic";
        case scene::SplineKind::Cubic: return "cubic";
        case scene::SplineKind::Bezier: return "Bezier";
    }
    return "linear";
}

// The spline keyword, if the next item is one.
bool accept_spline(ItemCursor& cur, scene::SplineKind& kind) {
    static const std::pair<const char*, scene::SplineKind> kWords[] = {
        {"linear_spline", scene::SplineKind::Linear},
        {"quadratic_spline", scene::SplineKind::Quadratic},
        {"cubic_spline", scene::SplineKind::Cubic},
        {"bezier_spline", scene::SplineKind::Bezier}};
    for (const auto& [word, k] : kWords)
        if (cur.accept_keyword(word)) {
            kind = k;
            return true;
        }
    return false;
}

// N, then N 2-D points; `where` gets each point's location.
std::vector<glm::dvec2> read_points(ItemCursor& cur, int n, std::vector<SourceLoc>& where) {
    std::vector<glm::dvec2> points;
    for (int i = 0; i < n; ++i) {
        const std::vector<double> c = cur.expect_vecn("");
        points.emplace_back(c[0], c.size() > 1 ? c[1] : c[0]);
        where.push_back(cur.here());
    }
    return points;
}

// The fewest points a spline needs (POV-Ray's own counts for prism and lathe); Bezier splines
// need whole groups of four.
void check_count(ItemCursor& cur, SourceLoc loc, const char* shape, scene::SplineKind kind,
                 int n, const int (&fewest)[3]) {
    static const char* const kWords[] = {"", "", "two", "three", "four", "five", "six"};
    if (kind == scene::SplineKind::Bezier) {
        if (n < 4 || n % 4 != 0)
            cur.fail(loc, std::string("a ") + shape +
                              " with Bezier splines must have four points per segment");
        return;
    }
    const int least = fewest[static_cast<int>(kind)];
    if (n < least)
        cur.fail(loc, std::string("a ") + shape + " with " + spline_name(kind) +
                          " splines must have at least " + kWords[least] + " points");
}

// The modifiers, with `open` and `sturm` where the shape has them.
template <class T> scene::ObjectPtr finish(ItemCursor& cur, T shape, bool has_open) {
    scene::Object obj;
    obj.loc = cur.block_loc();
    bool open = false, sturm = false;
    auto flags = [&](const Item& item) {
        if (item.kind != Item::Kind::Keyword) return false;
        if (item.keyword == "sturm") return sturm = true;
        if (has_open && item.keyword == "open") return open = true;
        return false;
    };
    read_object_modifiers(cur, obj, flags,
                          has_open ? std::vector<std::string>{"open", "sturm"}
                                   : std::vector<std::string>{"sturm"});
    shape.sturm = sturm;
    if constexpr (requires { shape.open; }) shape.open = open;
    obj.shape = std::move(shape);
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace

scene::ObjectPtr build_prism(ItemCursor& cur) {
    scene::Prism prism;
    for (;;) {
        if (accept_spline(cur, prism.spline)) continue;
        if (cur.accept_keyword("linear_sweep")) prism.conic = false;
        else if (cur.accept_keyword("conic_sweep")) prism.conic = true;
        else break;
    }
    prism.height1 = cur.expect_float("");
    prism.height2 = cur.expect_float("");
    if (prism.height1 > prism.height2) std::swap(prism.height1, prism.height2);
    const int n = cur.expect_int("");
    const SourceLoc count_loc = cur.here();
    check_count(cur, count_loc, "prism", prism.spline, n, {3, 5, 6});
    std::vector<SourceLoc> where;
    prism.points = read_points(cur, n, where);
    const SourceLoc last = where.back();
    if (prism.spline == scene::SplineKind::Linear) {
        // An unclosed sub-polygon is closed by its first point, as POV-Ray does.
        size_t start = 0;
        for (size_t i = 1; i < prism.points.size(); ++i)
            if (i > start && scene::same_point(prism.points[i], prism.points[start])) start = i + 1;
        if (start < prism.points.size()) {
            cur.warn(last, "linear prism not closed: closing it");
            prism.points.push_back(prism.points[start]);
        }
    } else if (!scene::prism_walk(prism.spline, prism.points).closed) {
        // POV-Ray keeps an unclosed Bezier outline (never hit) and rejects the others.
        if (prism.spline != scene::SplineKind::Bezier)
            cur.fail(last, std::string("too few points in prism: its ") +
                               spline_name(prism.spline) +
                               " spline does not end on its first curve point (the second "
                               "point)");
        cur.warn(last, "prism not closed: ignoring it (it is never hit)");
        prism.closed = false;
    }
    return finish(cur, std::move(prism), true);
}

scene::ObjectPtr build_lathe(ItemCursor& cur) {
    scene::Lathe lathe;
    while (accept_spline(cur, lathe.spline)) {}
    const int n = cur.expect_int("");
    check_count(cur, cur.here(), "lathe", lathe.spline, n, {2, 3, 4});
    std::vector<SourceLoc> where;
    lathe.points = read_points(cur, n, where);
    return finish(cur, std::move(lathe), false);
}

scene::ObjectPtr build_sor(ItemCursor& cur) {
    scene::Sor sor;
    const int n = cur.expect_int("");
    if (n < 4) cur.fail(cur.here(), "a surface of revolution must have at least four points");
    std::vector<SourceLoc> where;
    sor.points = read_points(cur, n, where);
    // POV-Ray's checks: no negative radius, heights rising strictly from the second point to
    // the last but one, the last not below it (measured: objects/sor1.pov ends on two points
    // at the same height), and the first point's height apart from the third's (it sets the
    // first slope).
    const auto& p = sor.points;
    for (int i = 0; i < n; ++i) {
        const bool rises = i < 2 || p[i].y > p[i - 1].y || (i == n - 1 && p[i].y == p[i - 1].y);
        if (p[i].x < 0 || !rises || (i == 2 && p[0].y == p[2].y))
            cur.fail(where[i], "incorrect point in surface of revolution" +
                                   std::string(p[i].x < 0 ? ": negative radius"
                                                          : ": heights must rise from the "
                                                            "second point on"));
    }
    return finish(cur, std::move(sor), true);
}

}  // namespace lumen::interp

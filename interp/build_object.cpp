// Primitive shapes and `object { }` (povray-semantics.md §9.2): the shape's own arguments,
// then the shared object modifiers.
#include <cmath>

#include <glm/geometric.hpp>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

const std::vector<std::string> kNoExtra;

auto no_extra = [](const Item&) { return false; };

// `open` for cylinders and cones, `sturm` for tori.
template <class Flag> auto flag_keyword(const char* word, Flag& flag) {
    return [word, &flag](const Item& item) {
        if (item.kind != Item::Kind::Keyword || item.keyword != word) return false;
        flag = true;
        return true;
    };
}

glm::dvec3 unit_or_fail(ItemCursor& cur, const glm::dvec3& v, SourceLoc loc, const char* what) {
    double len = glm::length(v);
    if (!(len > 0.0)) cur.fail(loc, std::string(what) + " is a zero vector");
    return v / len;
}

glm::dvec3 read_point(ItemCursor& cur) {  // 2-D points (polygon) get z = 0
    std::vector<double> c = cur.expect_vecn("");
    if (c.size() == 1) return glm::dvec3(c[0]);
    return {c[0], c.size() > 1 ? c[1] : 0.0, c.size() > 2 ? c[2] : 0.0};
}

scene::Polygon read_polygon(ItemCursor& cur) {
    SourceLoc loc = cur.block_loc();
    int n = cur.expect_int("");
    if (n < 3) cur.fail(cur.here(), "a polygon needs at least 3 points");
    scene::Polygon poly;
    size_t start = 0;  // first point of the current sub-polygon
    for (int i = 0; i < n; ++i) {
        poly.points.push_back(read_point(cur));
        if (poly.points.size() - 1 > start &&
            glm::length(poly.points.back() - poly.points[start]) < 1e-10)
            start = poly.points.size();
    }
    if (start < poly.points.size()) {
        cur.warn(loc, "polygon not closed: closing it");
        poly.points.push_back(poly.points[start]);
    }
    return poly;
}

scene::Shape read_shape(ItemCursor& cur) {
    const std::string& kw = cur.what();
    if (kw == "sphere") {
        scene::Sphere s;
        s.center = cur.expect_vector("");
        s.radius = cur.expect_float("");
        return s;
    }
    if (kw == "plane") {
        scene::Plane p;
        SourceLoc loc = cur.next_is_vector_like() ? cur.peek().loc : cur.here();
        p.normal = unit_or_fail(cur, cur.expect_vector(""), loc, "the plane normal");
        p.distance = cur.expect_float("");
        return p;
    }
    if (kw == "box") {
        glm::dvec3 a = cur.expect_vector(""), b = cur.expect_vector("");
        return scene::Box{glm::min(a, b), glm::max(a, b)};
    }
    if (kw == "cylinder") {
        scene::Cylinder c;
        c.base = cur.expect_vector("");
        c.cap = cur.expect_vector("");
        c.radius = cur.expect_float("");
        if (c.base == c.cap) cur.fail(cur.block_loc(), "degenerate cylinder: base equals cap");
        return c;
    }
    if (kw == "cone") {
        scene::Cone c;
        c.base = cur.expect_vector("");
        c.base_radius = cur.expect_float("");
        c.cap = cur.expect_vector("");
        c.cap_radius = cur.expect_float("");
        if (c.base == c.cap) cur.fail(cur.block_loc(), "degenerate cone: base equals cap");
        return c;
    }
    if (kw == "torus") {
        scene::Torus t;
        t.major = cur.expect_float("");
        t.minor = cur.expect_float("");
        return t;
    }
    if (kw == "disc") {
        scene::Disc d;
        d.center = cur.expect_vector("");
        SourceLoc loc = cur.next_is_vector_like() ? cur.peek().loc : cur.here();
        d.normal = unit_or_fail(cur, cur.expect_vector(""), loc, "the disc normal");
        d.radius = cur.expect_float("");
        if (auto hole = cur.optional_float()) d.hole = *hole;
        return d;
    }
    if (kw == "triangle") {
        scene::Triangle t;
        for (auto& p : t.p) p = cur.expect_vector("");
        return t;
    }
    if (kw == "smooth_triangle") {
        scene::Triangle t;
        t.smooth = true;
        for (int i = 0; i < 3; ++i) {
            t.p[i] = cur.expect_vector("");
            glm::dvec3 n = cur.expect_vector("");
            t.n[i] = glm::length(n) > 0 ? glm::normalize(n) : n;
        }
        return t;
    }
    if (kw == "polygon") return read_polygon(cur);
    cur.fail(cur.block_loc(), "'" + kw + "' is not a shape");
}

}  // namespace

scene::ObjectPtr unsupported_object(const scene::Unsupported& u) {
    auto obj = std::make_shared<scene::Object>();
    obj->shape = scene::UnsupportedShape{u};
    obj->loc = u.loc;
    return obj;
}

bool is_unsupported_shape(const std::string& keyword) {
    static const std::vector<std::string> shapes = {
        "bicubic_patch", "blob", "cubic", "height_field", "isosurface", "julia_fractal",
        "lathe", "lemon", "light_group", "ovus", "parametric", "poly", "polynomial", "prism",
        "quadric", "quartic", "sor", "sphere_sweep", "superellipsoid", "text"};
    for (const std::string& s : shapes)
        if (s == keyword) return true;
    return false;
}

scene::ObjectPtr build_object(ItemCursor& cur) {
    const std::string& kw = cur.what();
    if (kw == "union" || kw == "merge" || kw == "intersection" || kw == "difference")
        return build_csg(cur);
    if (kw == "mesh") return build_mesh(cur);
    if (kw == "mesh2") return build_mesh2(cur);
    scene::Object obj;
    if (kw == "object") {
        if (cur.next_is<scene::ObjectPtr>()) {
            obj = *cur.next().value.as<scene::ObjectPtr>();
        } else if (cur.next_is<scene::Unsupported>()) {
            obj = *unsupported_object(cur.next().value.as<scene::Unsupported>());
        } else {
            cur.fail_expected("an object", "");
        }
        obj.loc = cur.block_loc();
        // The copied shape's own flags may be set again: `object { Torus sturm }`.
        auto shape_flag = [&](const Item& item) {
            if (item.kind != Item::Kind::Keyword) return false;
            if (item.keyword == "sturm") {
                if (auto* t = std::get_if<scene::Torus>(&obj.shape)) t->sturm = true;
                return true;
            }
            if (item.keyword != "open") return false;
            if (auto* c = std::get_if<scene::Cylinder>(&obj.shape)) c->open = true;
            if (auto* c = std::get_if<scene::Cone>(&obj.shape)) c->open = true;
            return true;
        };
        read_object_modifiers(cur, obj, shape_flag, {"sturm", "open"});
        return std::make_shared<scene::Object>(std::move(obj));
    }
    obj.loc = cur.block_loc();
    bool open = false, sturm = false;
    obj.shape = read_shape(cur);
    if (kw == "cylinder" || kw == "cone") {
        read_object_modifiers(cur, obj, flag_keyword("open", open), {"open"});
        if (auto* c = std::get_if<scene::Cylinder>(&obj.shape)) c->open = open;
        if (auto* c = std::get_if<scene::Cone>(&obj.shape)) c->open = open;
    } else if (kw == "torus") {
        read_object_modifiers(cur, obj, flag_keyword("sturm", sturm), {"sturm"});
        std::get<scene::Torus>(obj.shape).sturm = sturm;
    } else if (kw == "triangle" || kw == "smooth_triangle") {
        // Mesh triangles may carry `uv_vectors <u,v> <u,v> <u,v>`: only uv_mapping uses them.
        auto uv = [&](const Item& item) {
            if (item.kind != Item::Kind::Keyword || item.keyword != "uv_vectors") return false;
            for (int i = 0; i < 3; ++i) cur.expect_vecn("uv_vectors");
            return true;
        };
        read_object_modifiers(cur, obj, uv, {"uv_vectors"});
    } else {
        read_object_modifiers(cur, obj, no_extra, kNoExtra);
    }
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace lumen::interp

// Primitive shapes and `object { }`: as in POV-Ray, a shape's own arguments come first, then
// the object modifiers shared by every object (and the shape's own flags: open, sturm, ...).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string_view>
#include <type_traits>

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

// An object of the shape just read: the object modifiers follow its arguments, and `extra`
// takes the shape's own modifier keywords (`words`).
template <class Extra = decltype(no_extra)>
scene::Object object_of(ItemCursor& cur, scene::Shape shape, const Extra& extra = no_extra,
                        const std::vector<std::string>& words = kNoExtra) {
    scene::Object obj;
    obj.loc = cur.block_loc();
    obj.shape = std::move(shape);
    read_object_modifiers(cur, obj, extra, words);
    return obj;
}

scene::ObjectPtr share(scene::Object obj) { return std::make_shared<scene::Object>(std::move(obj)); }

// An object whose shape has a flag keyword of its own among its modifiers (open, sturm).
template <class T>
scene::ObjectPtr object_with_flag(ItemCursor& cur, const T& shape, const char* word,
                                  bool T::*flag) {
    bool set = false;
    scene::Object obj = object_of(cur, shape, flag_keyword(word, set), {word});
    std::get<T>(obj.shape).*flag = set;
    return share(std::move(obj));
}

// Cylinders and cones: the axis needs a length, and `open` drops the caps.
template <class T>
scene::ObjectPtr axis_object(ItemCursor& cur, const T& shape, const char* what) {
    if (shape.base == shape.cap)
        cur.fail(cur.block_loc(), std::string("degenerate ") + what + ": base equals cap");
    return object_with_flag(cur, shape, "open", &T::open);
}

// One reader per shape of scene/shape_list.hpp: the block after its keyword. Arguments read
// in braced initialisers are read in order (C++ evaluates those left to right).

scene::ObjectPtr read_primitive(std::type_identity<scene::Sphere>, ItemCursor& cur) {
    scene::Sphere s{cur.expect_vector(""), cur.expect_float("")};
    return share(object_of(cur, s));
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Plane>, ItemCursor& cur) {
    scene::Plane p;
    SourceLoc loc = cur.next_is_vector_like() ? cur.peek().loc : cur.here();
    p.normal = unit_or_fail(cur, cur.expect_vector(""), loc, "the plane normal");
    p.distance = cur.expect_float("");
    return share(object_of(cur, p));
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Box>, ItemCursor& cur) {
    glm::dvec3 a = cur.expect_vector(""), b = cur.expect_vector("");
    return share(object_of(cur, scene::Box{glm::min(a, b), glm::max(a, b)}));
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Cylinder>, ItemCursor& cur) {
    scene::Cylinder c{cur.expect_vector(""), cur.expect_vector(""), cur.expect_float("")};
    return axis_object(cur, c, "cylinder");
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Cone>, ItemCursor& cur) {
    scene::Cone c{cur.expect_vector(""), cur.expect_float(""), cur.expect_vector(""),
                  cur.expect_float("")};
    return axis_object(cur, c, "cone");
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Torus>, ItemCursor& cur) {
    scene::Torus t{cur.expect_float(""), cur.expect_float("")};
    return object_with_flag(cur, t, "sturm", &scene::Torus::sturm);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Disc>, ItemCursor& cur) {
    scene::Disc d;
    d.center = cur.expect_vector("");
    SourceLoc loc = cur.next_is_vector_like() ? cur.peek().loc : cur.here();
    d.normal = unit_or_fail(cur, cur.expect_vector(""), loc, "the disc normal");
    d.radius = cur.expect_float("");
    if (auto hole = cur.optional_float()) d.hole = *hole;
    return share(object_of(cur, d));
}

// triangle and smooth_triangle.
scene::ObjectPtr read_primitive(std::type_identity<scene::Triangle>, ItemCursor& cur) {
    scene::Triangle t;
    t.smooth = cur.what() == "smooth_triangle";
    for (int i = 0; i < 3; ++i) {
        t.p[i] = cur.expect_vector("");
        if (!t.smooth) continue;
        glm::dvec3 n = cur.expect_vector("");
        t.n[i] = glm::length(n) > 0 ? glm::normalize(n) : n;
    }
    // Mesh triangles may carry `uv_vectors <u,v> <u,v> <u,v>` (default all 0, as in POV-Ray).
    std::array<glm::dvec2, 3> uvs{};
    auto uv = [&](const Item& item) {
        if (item.kind != Item::Kind::Keyword || item.keyword != "uv_vectors") return false;
        for (glm::dvec2& each : uvs) each = read_vector2(cur, "uv_vectors");
        return true;
    };
    scene::Object obj = object_of(cur, t, uv, {"uv_vectors"});
    std::get<scene::Triangle>(obj.shape).uv = uvs;
    return share(std::move(obj));
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Polygon>, ItemCursor& cur) {
    return share(object_of(cur, read_polygon(cur)));
}

// mesh and mesh2 (build_mesh.cpp), and bicubic_patch, which renders as the mesh of its
// subdivision (build_bicubic_patch.cpp).
scene::ObjectPtr read_primitive(std::type_identity<scene::Mesh>, ItemCursor& cur) {
    if (cur.what() == "bicubic_patch") return build_bicubic_patch(cur);
    return cur.what() == "mesh" ? build_mesh(cur) : build_mesh2(cur);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Text>, ItemCursor& cur) {
    return build_text(cur);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Prism>, ItemCursor& cur) {
    return build_prism(cur);
}
scene::ObjectPtr read_primitive(std::type_identity<scene::Lathe>, ItemCursor& cur) {
    return build_lathe(cur);
}
scene::ObjectPtr read_primitive(std::type_identity<scene::Sor>, ItemCursor& cur) {
    return build_sor(cur);
}

// polynomial { Order, xyz(i, j, k): c ... }: named terms, the others 0; a term written again
// replaces the earlier value (measured with POV-Ray 3.7).
scene::ObjectPtr read_polynomial(ItemCursor& cur) {
    scene::Poly p;
    SourceLoc loc = cur.next_loc();
    p.order = cur.expect_int("");
    if (p.order < 2 || p.order > 35)
        cur.fail(loc, "polynomial order must be 2 to 35, not " + std::to_string(p.order));
    p.coeffs.assign(scene::Poly::term_count(p.order), 0.0);
    auto term = [&](const Item& item) {
        if (item.kind != Item::Kind::Keyword || item.keyword != "xyz") return false;
        const Item& value = cur.next();
        const std::vector<double>& t = value.value.as<VecN>().c;
        int power[3];
        for (int a = 0; a < 3; ++a) {
            power[a] = int(t[a]);
            if (power[a] < 0 || double(power[a]) != t[a])
                cur.fail(item.loc, "xyz powers must be whole numbers from 0");
        }
        if (power[0] + power[1] + power[2] > p.order)
            cur.fail(item.loc, "the term's powers add up to more than the order " +
                                   std::to_string(p.order));
        p.coeffs[scene::Poly::term_index(p.order, power[0], power[1], power[2])] = t[3];
        return true;
    };
    bool sturm = false;
    auto extra = [&](const Item& item) { return term(item) || flag_keyword("sturm", sturm)(item); };
    scene::Object obj = object_of(cur, p, extra, {"xyz", "sturm"});
    std::get<scene::Poly>(obj.shape).coeffs = p.coeffs;
    std::get<scene::Poly>(obj.shape).sturm = sturm;
    return share(std::move(obj));
}

// poly { Order, <coefficients> [sturm] }, cubic { <20> }, quartic { <35> }: exactly the
// number of terms of the order, as POV-Ray requires.
scene::ObjectPtr read_primitive(std::type_identity<scene::Poly>, ItemCursor& cur) {
    if (cur.what() == "polynomial") return read_polynomial(cur);
    scene::Poly p;
    if (cur.what() == "cubic") {
        p.order = 3;
    } else if (cur.what() == "quartic") {
        p.order = 4;
    } else {
        SourceLoc loc = cur.next_loc();
        p.order = cur.expect_int("");
        if (p.order < 2 || p.order > 35)
            cur.fail(loc, "poly order must be 2 to 35, not " + std::to_string(p.order));
    }
    SourceLoc loc = cur.next_loc();
    p.coeffs = cur.expect_vecn("");
    const size_t terms = scene::Poly::term_count(p.order);
    if (p.coeffs.size() != terms)
        cur.fail(loc, "a " + cur.what() + " of order " + std::to_string(p.order) + " needs " +
                          std::to_string(terms) + " coefficients, found " +
                          std::to_string(p.coeffs.size()));
    return object_with_flag(cur, p, "sturm", &scene::Poly::sturm);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Quadric>, ItemCursor& cur) {
    scene::Quadric q;
    q.square = cur.expect_vector("");
    q.mixed = cur.expect_vector("");
    q.linear = cur.expect_vector("");
    q.constant = cur.expect_float("");
    return share(object_of(cur, q));
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Superellipsoid>, ItemCursor& cur) {
    SourceLoc loc = cur.next_loc();
    std::vector<double> en = cur.expect_vecn("");
    if (en.size() == 1) en.push_back(en[0]);  // a float is <f, f>, as for any 2-D vector
    if (en.size() != 2) cur.fail(loc, "superellipsoid needs a 2-D vector <e, n>");
    return share(object_of(cur, scene::Superellipsoid{en[0], en[1]}));
}

// ovus { bottom, top }: POV-Ray refuses negative radii, and makes a top radius of twice the
// bottom one or more the sphere the ovus would be (with its warning).
scene::ObjectPtr read_primitive(std::type_identity<scene::Ovus>, ItemCursor& cur) {
    scene::Ovus o;
    for (double* r : {&o.bottom, &o.top}) {
        const SourceLoc loc = cur.next_loc();
        *r = cur.expect_float("");
        if (!(*r >= 0) || !std::isfinite(*r)) cur.fail(loc, "both ovus radii must be positive");
    }
    if (o.top >= 2 * o.bottom) {
        cur.warn(cur.block_loc(), "an ovus's top radius of twice its bottom radius or more makes "
                                  "it a sphere: rendered as one");
        return share(object_of(cur, scene::Sphere{{0, o.bottom, 0}, o.top}));
    }
    return share(object_of(cur, o));
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Blob>, ItemCursor& cur) {
    return build_blob(cur);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::HeightField>, ItemCursor& cur) {
    return build_height_field(cur);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::JuliaFractal>, ItemCursor& cur) {
    return build_julia_fractal(cur);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::SphereSweep>, ItemCursor& cur) {
    return build_sphere_sweep(cur);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Isosurface>, ItemCursor& cur) {
    return build_isosurface(cur);
}

scene::ObjectPtr read_primitive(std::type_identity<scene::Parametric>, ItemCursor& cur) {
    return build_parametric(cur);
}

bool is_keyword_of(const std::string& kw, std::initializer_list<std::string_view> words) {
    return std::find(words.begin(), words.end(), kw) != words.end();
}

}  // namespace

// A copy of a declared object: `object { Ident modifiers }`.
scene::ObjectPtr read_object_copy(ItemCursor& cur) {
    scene::Object obj;
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
            if (auto* p = std::get_if<scene::Poly>(&obj.shape)) p->sturm = true;
            return true;
        }
        if (item.keyword != "open") return false;
        if (auto* c = std::get_if<scene::Cylinder>(&obj.shape)) c->open = true;
        if (auto* c = std::get_if<scene::Cone>(&obj.shape)) c->open = true;
        return true;
    };
    read_object_modifiers(cur, obj, shape_flag, {"sturm", "open"});
    return share(std::move(obj));
}

scene::ObjectPtr unsupported_object(const scene::Unsupported& u) {
    auto obj = std::make_shared<scene::Object>();
    obj->shape = scene::UnsupportedShape{u};
    obj->loc = u.loc;
    return obj;
}

bool is_unsupported_shape(const std::string& keyword) {
    const auto& shapes = scene::kUnsupportedShapeKeywords;
    return std::find(std::begin(shapes), std::end(shapes), keyword) != std::end(shapes);
}

scene::ObjectPtr build_object(ItemCursor& cur) {
    const std::string& kw = cur.what();
    if (kw == "union" || kw == "merge" || kw == "intersection" || kw == "difference" ||
        kw == "light_group")
        return build_csg(cur);
    if (kw == "object") return read_object_copy(cur);
#define LUMEN_READ_SHAPE(T, ...) \
    if (is_keyword_of(kw, {__VA_ARGS__})) return read_primitive(std::type_identity<scene::T>{}, cur);
    LUMEN_PRIMITIVE_SHAPES(LUMEN_READ_SHAPE)
#undef LUMEN_READ_SHAPE
    cur.fail(cur.block_loc(), "'" + kw + "' is not a shape");
}

}  // namespace lumen::interp

#include "interp/dump_scene.hpp"

#include <cmath>
#include <cstdio>

#include "interp/dump_atmosphere.hpp"
#include "interp/dump_pattern.hpp"
#include "interp/dump_photons.hpp"

namespace lumen::interp {

namespace {

using namespace dump;

std::string format_number(double v) {
    if (std::isnan(v)) return "\"nan\"";
    if (std::isinf(v)) return v > 0 ? "\"inf\"" : "\"-inf\"";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    std::string s = buf;
    return s == "-0" ? "0" : s;
}

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
            continue;
        }
        out += c;
    }
    return out + "\"";
}

void print(const Json& j, int indent, std::string& out) {
    std::string pad(indent * 2, ' '), inner((indent + 1) * 2, ' ');
    switch (j.kind) {
        case Json::Kind::Number: out += format_number(j.number); return;
        case Json::Kind::String: out += quote(j.text); return;
        case Json::Kind::Bool: out += j.flag ? "true" : "false"; return;
        case Json::Kind::Array: {
            bool inline_form = true;
            for (const Json& e : j.items)  // numbers on one line, strings one per line
                inline_form = inline_form && e.scalar() && e.kind != Json::Kind::String;
            out += "[";
            for (size_t i = 0; i < j.items.size(); ++i) {
                if (inline_form) out += i ? ", " : "";
                else out += (i ? ",\n" : "\n") + inner;
                print(j.items[i], indent + 1, out);
            }
            if (!inline_form && !j.items.empty()) out += "\n" + pad;
            out += "]";
            return;
        }
        case Json::Kind::Object: {
            out += "{";
            for (size_t i = 0; i < j.keys.size(); ++i) {
                out += (i ? ",\n" : "\n") + inner + quote(j.keys[i]) + ": ";
                print(j.values[i], indent + 1, out);
            }
            if (!j.keys.empty()) out += "\n" + pad;
            out += "}";
            return;
        }
    }
}

// ---- values ---------------------------------------------------------------------------------

Json pigment(const scene::Pigment& p) {
    const scene::Pigment d;
    Json o;
    put_nonempty(o, "pattern", pattern(p.pattern));
    put_if(o, "colour", p.colour, d.colour);
    put_nonempty(o, "colour_map", colour_map(p.colour_map));
    Json pm = Json::array();
    for (const auto& e : p.pigment_map) {
        Json entry;
        entry.put("value", Json::num(e.value));
        if (e.item) entry.put("pigment", pigment(*e.item));
        pm.push(entry);
    }
    put_nonempty(o, "pigment_map", pm);
    put_if(o, "list_form", p.list_form, d.list_form);
    return o;
}

Json finish(const scene::Finish& f) {
    const scene::Finish d;
    Json o;
    put_if(o, "ambient", f.ambient, d.ambient);
    put_if(o, "emission", f.emission, d.emission);
    put_if(o, "diffuse", f.diffuse, d.diffuse);
    put_if(o, "diffuse_back", f.diffuse_back, d.diffuse_back);
    put_if(o, "brilliance", f.brilliance, d.brilliance);
    put_if(o, "phong", f.phong, d.phong);
    put_if(o, "phong_size", f.phong_size, d.phong_size);
    put_if(o, "specular", f.specular, d.specular);
    put_if(o, "roughness", f.roughness, d.roughness);
    put_if(o, "metallic", f.metallic, d.metallic);
    put_if(o, "crand", f.crand, d.crand);
    put_if(o, "reflection_min", f.reflection_min, d.reflection_min);
    put_if(o, "reflection_max", f.reflection_max, d.reflection_max);
    put_if(o, "reflection_falloff", f.reflection_falloff, d.reflection_falloff);
    put_if(o, "reflection_exponent", f.reflection_exponent, d.reflection_exponent);
    put_if(o, "reflection_metallic", f.reflection_metallic, d.reflection_metallic);
    put_if(o, "fresnel", f.fresnel, d.fresnel);
    put_if(o, "conserve_energy", f.conserve_energy, d.conserve_energy);
    put_if(o, "irid_amount", f.irid_amount, d.irid_amount);
    put_if(o, "irid_thickness", f.irid_thickness, d.irid_thickness);
    put_if(o, "irid_turbulence", f.irid_turbulence, d.irid_turbulence);
    if (f.ior) o.put("ior", Json::num(*f.ior));
    return o;
}

Json normal(const scene::Normal& n) {
    const scene::Normal d;
    Json o;
    put_nonempty(o, "pattern", pattern(n.pattern));
    put_if(o, "amount", n.amount, d.amount);
    put_if(o, "accuracy", n.accuracy, d.accuracy);
    put_if(o, "no_bump_scale", n.no_bump_scale, d.no_bump_scale);
    Json nm = Json::array();
    for (const auto& e : n.normal_map) {
        Json entry;
        entry.put("value", Json::num(e.value));
        if (e.item) entry.put("normal", normal(*e.item));
        nm.push(entry);
    }
    put_nonempty(o, "normal_map", nm);
    Json sm = Json::array();
    for (const auto& e : n.slope_map)
        sm.push(Json::array().push(Json::num(e.value)).push(Json::num(e.item.x)).push(Json::num(e.item.y)));
    put_nonempty(o, "slope_map", sm);
    return o;
}

Json layered(const scene::LayeredTexture& layers);

Json texture(const scene::Texture& t) {
    Json o;
    if (t.pigment) o.put("pigment", pigment(*t.pigment));
    if (t.finish) o.put("finish", finish(*t.finish));
    if (t.normal) o.put("normal", normal(*t.normal));
    put_nonempty(o, "pattern", pattern(t.pattern));
    Json tm = Json::array();
    for (const auto& e : t.texture_map) {
        Json entry;
        entry.put("value", Json::num(e.value));
        entry.put("texture", layered(e.item));
        tm.push(entry);
    }
    put_nonempty(o, "texture_map", tm);
    put_if(o, "list_form", t.list_form, false);
    return o;
}

Json layered(const scene::LayeredTexture& layers) {
    Json a = Json::array();
    for (const auto& l : layers) a.push(l ? texture(*l) : Json());
    return a;
}

Json interior(const scene::Interior& in) {
    const scene::Interior d;
    Json o;
    put_if(o, "ior", in.ior, d.ior);
    put_if(o, "caustics", in.caustics, d.caustics);
    put_if(o, "dispersion", in.dispersion, d.dispersion);
    put_if(o, "dispersion_samples", double(in.dispersion_samples), double(d.dispersion_samples));
    put_if(o, "fade_distance", in.fade_distance, d.fade_distance);
    put_if(o, "fade_power", in.fade_power, d.fade_power);
    put_if(o, "fade_colour", in.fade_colour, d.fade_colour);
    if (!in.media.empty()) o.put("media", Json::num(double(in.media.size())));
    return o;
}

Json object(const scene::Object& obj);

struct ShapeDumper {
    Json& o;
    void operator()(const scene::Sphere& s) const {
        o.put("type", Json::str("sphere"));
        put_if(o, "center", s.center, scene::Sphere{}.center);
        put_if(o, "radius", s.radius, scene::Sphere{}.radius);
    }
    void operator()(const scene::Plane& p) const {
        o.put("type", Json::str("plane"));
        put_if(o, "normal", p.normal, scene::Plane{}.normal);
        put_if(o, "distance", p.distance, scene::Plane{}.distance);
    }
    void operator()(const scene::Box& b) const {
        o.put("type", Json::str("box"));
        put_if(o, "min", b.min, scene::Box{}.min);
        put_if(o, "max", b.max, scene::Box{}.max);
    }
    void operator()(const scene::Cylinder& c) const {
        const scene::Cylinder d;
        o.put("type", Json::str("cylinder"));
        put_if(o, "base", c.base, d.base);
        put_if(o, "cap", c.cap, d.cap);
        put_if(o, "radius", c.radius, d.radius);
        put_if(o, "open", c.open, d.open);
    }
    void operator()(const scene::Cone& c) const {
        const scene::Cone d;
        o.put("type", Json::str("cone"));
        put_if(o, "base", c.base, d.base);
        put_if(o, "base_radius", c.base_radius, d.base_radius);
        put_if(o, "cap", c.cap, d.cap);
        put_if(o, "cap_radius", c.cap_radius, d.cap_radius);
        put_if(o, "open", c.open, d.open);
    }
    void operator()(const scene::Torus& t) const {
        const scene::Torus d;
        o.put("type", Json::str("torus"));
        put_if(o, "major", t.major, d.major);
        put_if(o, "minor", t.minor, d.minor);
        put_if(o, "sturm", t.sturm, d.sturm);
    }
    void operator()(const scene::Disc& c) const {
        const scene::Disc d;
        o.put("type", Json::str("disc"));
        put_if(o, "center", c.center, d.center);
        put_if(o, "normal", c.normal, d.normal);
        put_if(o, "radius", c.radius, d.radius);
        put_if(o, "hole", c.hole, d.hole);
    }
    void operator()(const scene::Triangle& t) const {
        o.put("type", Json::str(t.smooth ? "smooth_triangle" : "triangle"));
        Json pts = Json::array();
        for (const auto& p : t.p) pts.push(vec(p));
        o.put("points", pts);
        if (t.smooth) {
            Json ns = Json::array();
            for (const auto& n : t.n) ns.push(vec(n));
            o.put("normals", ns);
        }
    }
    void operator()(const scene::Polygon& p) const {
        o.put("type", Json::str("polygon"));
        Json pts = Json::array();
        for (const auto& v : p.points) pts.push(vec(v));
        o.put("points", pts);
    }
    void operator()(const scene::Mesh& m) const {
        o.put("type", Json::str("mesh"));
        Json vs = Json::array(), ns = Json::array(), uvs = Json::array(), fs = Json::array(),
             ts = Json::array();
        for (const auto& v : m.vertices) vs.push(vec(v));
        for (const auto& n : m.normals) ns.push(vec(n));
        for (const auto& uv : m.uvs) uvs.push(Json::array().push(Json::num(uv.x)).push(Json::num(uv.y)));
        auto triple = [](const std::array<int, 3>& t) {
            return Json::array().push(Json::num(t[0])).push(Json::num(t[1])).push(Json::num(t[2]));
        };
        // A face is its vertex triple, or {"v", "n", "tex"} when it has normals or textures.
        for (const auto& f : m.faces) {
            if (f.n[0] < 0 && f.tex[0] < 0) {
                fs.push(triple(f.v));
                continue;
            }
            Json face;
            face.put("v", triple(f.v));
            if (f.n[0] >= 0) face.put("n", triple(f.n));
            if (f.tex[0] >= 0) face.put("tex", triple(f.tex));
            fs.push(face);
        }
        for (const auto& t : m.textures) ts.push(layered(t));
        o.put("vertices", vs);
        put_nonempty(o, "normals", ns);
        put_nonempty(o, "uvs", uvs);
        o.put("faces", fs);
        put_nonempty(o, "textures", ts);
        if (m.inside_vector) o.put("inside_vector", vec(*m.inside_vector));
    }
    // The font as found, the string, and where each glyph went with its outline's size.
    void operator()(const scene::Text& t) const {
        o.put("type", Json::str("text"));
        o.put("font", Json::str(t.font));
        o.put("string", Json::str(t.string));
        o.put("thickness", Json::num(t.thickness));
        o.put("offset", vec(t.offset));
        Json gs = Json::array();
        for (const auto& g : t.glyphs) {
            Json glyph;
            glyph.put("position", vec(g.position));
            glyph.put("points", Json::num(double(g.points.size())));
            glyph.put("contours", Json::num(double(g.contour_ends.size())));
            gs.push(glyph);
        }
        o.put("glyphs", gs);
    }
    // prism, lathe and sor: the spline, the points as read (a linear prism closed) and flags.
    static Json points2(const std::vector<glm::dvec2>& pts) {
        Json a = Json::array();
        for (const auto& p : pts) a.push(Json::array().push(Json::num(p.x)).push(Json::num(p.y)));
        return a;
    }
    static Json spline(scene::SplineKind k) {
        static const char* names[] = {"linear_spline", "quadratic_spline", "cubic_spline",
                                      "bezier_spline"};
        return Json::str(names[static_cast<int>(k)]);
    }
    void operator()(const scene::Prism& p) const {
        const scene::Prism d;
        o.put("type", Json::str("prism"));
        o.put("spline", spline(p.spline));
        o.put("sweep", Json::str(p.conic ? "conic_sweep" : "linear_sweep"));
        o.put("height1", Json::num(p.height1));
        o.put("height2", Json::num(p.height2));
        o.put("points", points2(p.points));
        put_if(o, "open", p.open, d.open);
        put_if(o, "sturm", p.sturm, d.sturm);
        put_if(o, "closed", p.closed, d.closed);
    }
    void operator()(const scene::Lathe& l) const {
        o.put("type", Json::str("lathe"));
        o.put("spline", spline(l.spline));
        o.put("points", points2(l.points));
        put_if(o, "sturm", l.sturm, false);
    }
    void operator()(const scene::Sor& s) const {
        o.put("type", Json::str("sor"));
        o.put("points", points2(s.points));
        put_if(o, "open", s.open, false);
        put_if(o, "sturm", s.sturm, false);
    }
    // The order and every coefficient in POV-Ray's term order.
    void operator()(const scene::Poly& p) const {
        o.put("type", Json::str("poly"));
        o.put("order", Json::num(p.order));
        Json cs = Json::array();
        for (double c : p.coeffs) cs.push(Json::num(c));
        o.put("coeffs", cs);
        put_if(o, "sturm", p.sturm, false);
    }
    void operator()(const scene::Quadric& q) const {
        o.put("type", Json::str("quadric"));
        o.put("square", vec(q.square));
        o.put("mixed", vec(q.mixed));
        o.put("linear", vec(q.linear));
        o.put("constant", Json::num(q.constant));
    }
    void operator()(const scene::Superellipsoid& s) const {
        o.put("type", Json::str("superellipsoid"));
        o.put("e", Json::num(s.e));
        o.put("n", Json::num(s.n));
    }
    void operator()(const scene::Blob& b) const {
        o.put("type", Json::str("blob"));
        o.put("threshold", Json::num(b.threshold));
        Json cs = Json::array();
        for (const auto& c : b.components) {
            Json j;
            j.put("kind", Json::str(c.cylinder ? "cylinder" : "sphere"));
            j.put(c.cylinder ? "base" : "center", vec(c.a));
            if (c.cylinder) j.put("cap", vec(c.b));
            j.put("radius", Json::num(c.radius));
            j.put("strength", Json::num(c.strength));
            if (c.transform) put_transform(j, *c.transform);
            put_nonempty(j, "texture", layered(c.texture));
            cs.push(j);
        }
        o.put("components", cs);
        if (b.sturm) o.put("sturm", Json::boolean(true));
        if (!b.hierarchy) o.put("hierarchy", Json::boolean(false));
    }
    void operator()(const scene::Ovus& v) const {
        o.put("type", Json::str("ovus"));
        o.put("bottom", Json::num(v.bottom));
        o.put("top", Json::num(v.top));
    }
    // The grid's size and a hash of its heights (not the values: a field has thousands).
    void operator()(const scene::HeightField& h) const {
        o.put("type", Json::str("height_field"));
        o.put("columns", Json::num(h.columns));
        o.put("rows", Json::num(h.rows));
        char hash[17];
        std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(h.heights_hash));
        o.put("heights_hash", Json::str(hash));
        o.put("water_level", Json::num(h.water_level));
        put_if(o, "smooth", h.smooth, false);
        put_if(o, "hierarchy", h.hierarchy, true);
    }
    void put_container(const scene::Container& c) const {
        if (c.sphere) {
            o.put("sphere_center", vec(c.center));
            o.put("sphere_radius", Json::num(c.radius));
        } else {
            o.put("box_lo", vec(c.lo));
            o.put("box_hi", vec(c.hi));
        }
    }
    void operator()(const scene::Isosurface& s) const {
        o.put("type", Json::str("isosurface"));
        o.put("instructions", Json::num(s.function ? double(s.function->code.size()) : 0));
        put_container(s.container);
        o.put("threshold", Json::num(s.threshold));
        o.put("accuracy", Json::num(s.accuracy));
        o.put("max_gradient", Json::num(s.max_gradient));
        if (s.evaluate) o.put("evaluate", vec(*s.evaluate));
        put_if(o, "open", s.open, false);
        o.put("max_trace", Json::num(s.max_trace));
    }
    void operator()(const scene::Parametric& s) const {
        o.put("type", Json::str("parametric"));
        Json sizes = Json::array();
        for (const fn::ProgramPtr& f : s.functions)
            sizes.push(Json::num(f ? double(f->code.size()) : 0));
        o.put("instructions", std::move(sizes));
        o.put("uv", points2({s.uv_lo, s.uv_hi}));
        put_container(s.container);
        o.put("accuracy", Json::num(s.accuracy));
        o.put("max_gradient", Json::num(s.max_gradient));
        if (s.precompute_depth) {
            o.put("precompute_depth", Json::num(s.precompute_depth));
            o.put("precompute", Json::str(std::string(s.precompute[0] ? "x" : "") +
                                          (s.precompute[1] ? "y" : "") +
                                          (s.precompute[2] ? "z" : "")));
        }
    }
    void operator()(const scene::SphereSweep& s) const {
        static const char* splines[] = {"linear_spline", "b_spline", "cubic_spline"};
        o.put("type", Json::str("sphere_sweep"));
        o.put("spline", Json::str(splines[static_cast<int>(s.spline)]));
        Json spheres = Json::array();
        for (const scene::Sphere& p : s.spheres) {
            Json j;
            j.put("center", vec(p.center));
            j.put("radius", Json::num(p.radius));
            spheres.push(j);
        }
        o.put("spheres", spheres);
        o.put("tolerance", Json::num(s.tolerance));
    }
    void operator()(const scene::JuliaFractal& j) const {
        static const char* fns[] = {"sqr",  "cube",  "exp",  "reciprocal", "sin",   "asin",
                                    "sinh", "asinh", "cos",  "acos",       "cosh",  "acosh",
                                    "tan",  "atan",  "tanh", "atanh",      "ln",    "pwr"};
        auto vec4 = [](const std::array<double, 4>& v) {
            Json a = Json::array();
            for (double c : v) a.push(Json::num(c));
            return a;
        };
        o.put("type", Json::str("julia_fractal"));
        o.put("c", vec4(j.c));
        o.put("algebra", Json::str(j.algebra == scene::JuliaAlgebra::Quaternion ? "quaternion"
                                                                                : "hypercomplex"));
        o.put("function", Json::str(fns[static_cast<int>(j.function)]));
        if (j.function == scene::JuliaFunction::Pwr)
            o.put("exponent", Json::array().push(Json::num(j.exponent.x)).push(Json::num(j.exponent.y)));
        o.put("max_iteration", Json::num(j.max_iteration));
        o.put("precision", Json::num(j.precision));
        o.put("slice", vec4(j.slice));
        o.put("slice_distance", Json::num(j.slice_distance));
        put_if(o, "csg_child", j.csg_child, false);
    }
    void operator()(const scene::Csg& c) const {
        static const char* ops[] = {"union", "merge", "intersection", "difference"};
        o.put("type", Json::str(c.is_light_group ? "light_group" : ops[static_cast<int>(c.op)]));
        put_if(o, "light_group", double(c.light_group), 0.0);
        put_if(o, "global_lights", c.global_lights, false);
    }
    void operator()(const scene::UnsupportedShape& u) const {
        o.put("type", Json::str("unsupported"));
        o.put("what", unsupported_text(u.what));
    }
};

Json objects(const std::vector<scene::ObjectPtr>& list) {
    Json a = Json::array();
    for (const auto& o : list) a.push(o ? object(*o) : Json());
    return a;
}

Json object(const scene::Object& obj) {
    const scene::Object d;
    Json o;
    o.put("loc", Json::str(loc_text(obj.loc)));
    std::visit(ShapeDumper{o}, obj.shape);
    put_transform(o, obj.transform);
    put_nonempty(o, "texture", layered(obj.texture));
    put_nonempty(o, "interior_texture", layered(obj.interior_texture));
    if (obj.interior) o.put("interior", interior(*obj.interior));
    put_nonempty(o, "clipped_by", objects(obj.clipped_by));
    put_nonempty(o, "bounded_by", objects(obj.bounded_by));
    put_if(o, "inverse", obj.inverse, d.inverse);
    put_if(o, "hollow", obj.hollow, d.hollow);
    put_if(o, "no_shadow", obj.no_shadow, d.no_shadow);
    put_if(o, "no_image", obj.no_image, d.no_image);
    put_if(o, "no_reflection", obj.no_reflection, d.no_reflection);
    put_if(o, "double_illuminate", obj.double_illuminate, d.double_illuminate);
    put_if(o, "no_radiosity", obj.no_radiosity, d.no_radiosity);
    if (obj.photons) o.put("photons", object_photons(*obj.photons));
    Json u = Json::array();
    for (const auto& x : obj.unsupported) u.push(unsupported_text(x));
    put_nonempty(o, "unsupported", u);
    if (const auto* csg = std::get_if<scene::Csg>(&obj.shape))
        o.put("children", objects(csg->children));
    return o;
}

Json camera(const scene::Camera& c) {
    const scene::Camera d;
    Json o;
    if (c.loc.file || c.loc.line) o.put("loc", Json::str(loc_text(c.loc)));
    if (c.type != d.type) o.put("type", Json::str(scene::kCameraKeywords[static_cast<int>(c.type)]));
    if (c.type == scene::CameraType::Cylinder) o.put("cylinder", Json::num(c.cylinder_type));
    put_if(o, "angle", c.angle, d.angle);
    if (c.type == scene::CameraType::Spherical) put_if(o, "vertical_angle", c.vertical_angle, d.vertical_angle);
    if (c.normal) o.put("normal", Json::boolean(true));
    if (c.blur) {
        Json b;
        b.put("aperture", Json::num(c.blur->aperture));
        b.put("samples", Json::str(std::to_string(c.blur->min_samples) + ".." +
                                   std::to_string(c.blur->max_samples)));
        b.put("confidence", Json::num(c.blur->confidence));
        b.put("variance", Json::num(c.blur->variance));
        b.put("focal_distance", Json::num(c.blur->focal_distance));
        o.put("focal_blur", b);
    }
    put_if(o, "location", c.location, d.location);
    put_if(o, "direction", c.direction, d.direction);
    put_if(o, "up", c.up, d.up);
    put_if(o, "right", c.right, d.right);
    if (c.unsupported) o.put("unsupported", unsupported_text(*c.unsupported));
    return o;
}

Json light(const scene::Light& l) {
    const scene::Light d;
    Json o;
    o.put("loc", Json::str(loc_text(l.loc)));
    static const char* types[] = {"point", "spotlight", "cylinder"};
    if (l.type != d.type) o.put("type", Json::str(types[static_cast<int>(l.type)]));
    put_if(o, "position", l.position, d.position);
    put_if(o, "colour", l.colour, d.colour);
    put_if(o, "parallel", l.parallel, d.parallel);
    put_if(o, "point_at", l.point_at, d.point_at);
    put_if(o, "radius", l.radius, d.radius);
    put_if(o, "falloff", l.falloff, d.falloff);
    put_if(o, "tightness", l.tightness, d.tightness);
    put_if(o, "shadowless", l.shadowless, d.shadowless);
    put_if(o, "fade_distance", l.fade_distance, d.fade_distance);
    put_if(o, "fade_power", l.fade_power, d.fade_power);
    if (l.area) {
        const scene::AreaLight ad;
        Json a;
        a.put("axis1", vec(l.area->axis1));
        a.put("axis2", vec(l.area->axis2));
        a.put("size1", Json::num(l.area->size1));
        a.put("size2", Json::num(l.area->size2));
        put_if(a, "adaptive", double(l.area->adaptive), double(ad.adaptive));
        put_if(a, "jitter", l.area->jitter, ad.jitter);
        put_if(a, "circular", l.area->circular, ad.circular);
        put_if(a, "orient", l.area->orient, ad.orient);
        o.put("area_light", a);
    }
    put_if(o, "area_illumination", l.area_illumination, d.area_illumination);
    put_if(o, "media_interaction", l.media_interaction, d.media_interaction);
    put_if(o, "media_attenuation", l.media_attenuation, d.media_attenuation);
    put_if(o, "group", double(l.group), 0.0);
    if (l.looks_like) o.put("looks_like", object(*l.looks_like));
    if (l.projected_through) o.put("projected_through", object(*l.projected_through));
    put_nonempty(o, "photons", light_photons(l.photons));
    Json u = Json::array();
    for (const auto& x : l.unsupported) u.push(unsupported_text(x));
    put_nonempty(o, "unsupported", u);
    return o;
}

Json radiosity(const scene::RadiositySettings& r) {
    const scene::RadiositySettings d;
    Json o;
    put_if(o, "count", double(r.count), double(d.count));
    put_if(o, "count_pool", double(r.count_pool), double(d.count_pool));
    put_if(o, "error_bound", r.error_bound, d.error_bound);
    put_if(o, "recursion_limit", double(r.recursion_limit), double(d.recursion_limit));
    put_if(o, "nearest_count", double(r.nearest_count), double(d.nearest_count));
    put_if(o, "pretrace_start", r.pretrace_start, d.pretrace_start);
    put_if(o, "pretrace_end", r.pretrace_end, d.pretrace_end);
    put_if(o, "low_error_factor", r.low_error_factor, d.low_error_factor);
    put_if(o, "gray_threshold", r.gray_threshold, d.gray_threshold);
    put_if(o, "minimum_reuse", r.minimum_reuse, d.minimum_reuse);
    put_if(o, "maximum_reuse", r.maximum_reuse, d.maximum_reuse);
    put_if(o, "brightness", r.brightness, d.brightness);
    put_if(o, "adc_bailout", r.adc_bailout, d.adc_bailout);
    put_if(o, "always_sample", r.always_sample, d.always_sample);
    put_if(o, "normal", r.normal, d.normal);
    put_if(o, "media", r.media, d.media);
    put_if(o, "max_sample", r.max_sample, d.max_sample);
    return o;
}

Json globals(const scene::GlobalSettings& g) {
    const scene::GlobalSettings d;
    Json o;
    if (g.assumed_gamma) o.put("assumed_gamma", Json::num(*g.assumed_gamma));
    put_if(o, "max_trace_level", double(g.max_trace_level), double(d.max_trace_level));
    put_if(o, "adc_bailout", g.adc_bailout, d.adc_bailout);
    put_if(o, "ambient_light", g.ambient_light, d.ambient_light);
    put_if(o, "irid_wavelength", g.irid_wavelength, d.irid_wavelength);
    put_if(o, "noise_generator", double(g.noise_generator), double(d.noise_generator));
    put_if(o, "number_of_waves", double(g.number_of_waves), double(d.number_of_waves));
    if (g.radiosity) o.put("radiosity", radiosity(*g.radiosity));
    if (g.photons) o.put("photons", global_photons(*g.photons));
    Json u = Json::array();
    for (const auto& x : g.unsupported) u.push(unsupported_text(x));
    put_nonempty(o, "unsupported", u);
    return o;
}

Json sky_sphere(const scene::SkySphere& s) {
    Json o;
    Json ps = Json::array();
    for (const auto& p : s.pigments) ps.push(p ? pigment(*p) : Json());
    put_nonempty(o, "pigments", ps);
    put_transform(o, s.transform);
    put_if(o, "emission", s.emission, scene::SkySphere{}.emission);
    return o;
}

}  // namespace

std::string dump_scene_json(const scene::Scene& s) {
    const scene::Scene d;
    Json root;
    put_if(root, "language_version", s.language_version, d.language_version);
    put_if(root, "version_given", s.version_given, d.version_given);
    put_nonempty(root, "camera", camera(s.camera));
    Json lights = Json::array();
    for (const auto& l : s.lights) lights.push(light(l));
    put_nonempty(root, "lights", lights);
    put_nonempty(root, "objects", objects(s.objects));
    put_nonempty(root, "globals", globals(s.globals));
    put_if(root, "background", s.background, d.background);
    if (s.sky_sphere) root.put("sky_sphere", sky_sphere(*s.sky_sphere));
    Json fogs = Json::array();
    for (const auto& f : s.fogs) fogs.push(fog(f));
    put_nonempty(root, "fogs", fogs);
    Json rainbows = Json::array();
    for (const auto& r : s.rainbows) rainbows.push(rainbow(r));
    put_nonempty(root, "rainbows", rainbows);
    Json u = Json::array();
    for (const auto& x : s.unsupported) u.push(unsupported_text(x));
    put_nonempty(root, "unsupported", u);
    std::string out;
    print(root, 0, out);
    return out + "\n";
}

}  // namespace lumen::interp

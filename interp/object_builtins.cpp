// Built-in functions that ask about an object: min_extent/max_extent (the box POV-Ray stores,
// scene/object_extents.cpp), and trace/inside, answered by the renderer through
// InterpOptions::object_queries.
#include <cmath>

#include <glm/geometric.hpp>

#include "interp/builtin_table.hpp"
#include "interp/conversions.hpp"
#include "scene/object_extents.hpp"

namespace lumen::interp {
namespace {

const scene::ObjectPtr& object_arg(const Value& v) {
    if (v.is<scene::Unsupported>()) unsupported_error(v.as<scene::Unsupported>());
    if (!v.is<scene::ObjectPtr>()) type_error(v, "an object");
    return v.as<scene::ObjectPtr>();
}

scene::ObjectQueries& queries(Evaluator& ev, const ast::Node& call) {
    if (!ev.options().object_queries)
        throw LumenError(call.loc, "'" + call.text + "' is not supported here (no renderer)");
    return *ev.options().object_queries;
}

// trace(Object, Start, Dir [, NormalVar]): the nearest hit's point, or <0,0,0> on a miss; the
// fourth argument, a declared identifier, receives the hit's normal (<0,0,0> on a miss).
Value trace(Evaluator& ev, const ast::Node& c) {
    const Value object = ev.eval(*c.children[0]);
    const scene::ObjectPtr& o = object_arg(object);
    const glm::dvec3 start = to_vec3(ev.eval(*c.children[1]));
    const glm::dvec3 dir = to_vec3(ev.eval(*c.children[2]));
    Value* normal_var = nullptr;
    if (c.children.size() == 4) {
        const ast::Node& n = *c.children[3];
        if (n.kind == ast::Kind::Ident) normal_var = ev.symbols.find(n.text);
        if (!normal_var)
            throw LumenError(n.loc, "trace's fourth argument must be a declared identifier");
    }
    std::optional<scene::ObjectQueries::Hit> hit;
    const double len = glm::length(dir);
    if (len > 0 && std::isfinite(len)) hit = queries(ev, c).trace(o, start, dir / len);
    if (normal_var) *normal_var = vec3_value(hit ? hit->normal : glm::dvec3(0), c.loc);
    return vec3_value(hit ? hit->point : glm::dvec3(0), c.loc);
}

}  // namespace

void add_object_builtins(BuiltinTable& t) {
    for (const bool max : {false, true})
        t[max ? "max_extent" : "min_extent"] = {
            1, 1, false, [max](Evaluator&, const ast::Node& c, Args& a) {
                const scene::Extents e = scene::object_extents(*object_arg(a[0]));
                return vec3_value(max ? e.max : e.min, c.loc);
            }};
    t["trace"] = {3, 4, true, [](Evaluator& ev, const ast::Node& c, Args&) { return trace(ev, c); }};
    t["inside"] = {2, 2, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                       const scene::ObjectPtr& o = object_arg(a[0]);
                       return Value{double(queries(ev, c).inside(o, to_vec3(a[1]))), c.loc};
                   }};
}

}  // namespace lumen::interp

// union / merge / intersection / difference: children first, then object modifiers.
// Children keep an empty texture when none was given: the renderer lets them inherit the
// CSG's texture. Light sources inside are kept apart and become scene lights when the CSG is
// placed in the scene.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

scene::CsgOp csg_op(const std::string& kw) {
    if (kw == "merge") return scene::CsgOp::Merge;
    if (kw == "intersection") return scene::CsgOp::Intersection;
    if (kw == "difference") return scene::CsgOp::Difference;
    return scene::CsgOp::Union;
}

// POV-Ray marks the objects of a CSG block as its children; a julia_fractal then lists all
// its crossings instead of only the first (render/shapes/julia_fractal.cpp).
scene::ObjectPtr in_csg(scene::ObjectPtr c) {
    const auto* j = std::get_if<scene::JuliaFractal>(&c->shape);
    if (!j || j->csg_child) return c;
    auto copy = std::make_shared<scene::Object>(*c);
    std::get<scene::JuliaFractal>(copy->shape).csg_child = true;
    return copy;
}

}  // namespace

scene::ObjectPtr build_csg(ItemCursor& cur) {
    scene::Object obj;
    obj.loc = cur.block_loc();
    scene::Csg& csg = obj.shape.emplace<scene::Csg>();
    csg.op = csg_op(cur.what());
    bool modifiers_seen = false;
    auto child = [&](const Item& item) {
        if (item.kind != Item::Kind::Value) return false;
        scene::ObjectPtr c;
        if (item.value.is<scene::ObjectPtr>()) {
            c = item.value.as<scene::ObjectPtr>();
        } else if (item.value.is<scene::Unsupported>() &&
                   is_unsupported_shape(item.value.as<scene::Unsupported>().feature)) {
            c = unsupported_object(item.value.as<scene::Unsupported>());
        } else if (item.value.is<std::shared_ptr<const scene::Light>>()) {
            csg.lights.push_back(item.value.as<std::shared_ptr<const scene::Light>>());
            return true;
        } else {
            modifiers_seen = true;
            return false;
        }
        // A child after a transform would not be moved by it the way POV moves children.
        if (modifiers_seen)
            cur.fail(item.loc, "objects must come before the modifiers in " + cur.what());
        csg.children.push_back(in_csg(std::move(c)));
        return true;
    };
    auto modifier = [&](const Item& item) {
        if (child(item)) return true;
        modifiers_seen = true;
        return false;
    };
    read_object_modifiers(cur, obj, modifier, {});
    if (csg.children.size() < 2 && csg.op != scene::CsgOp::Union)
        cur.warn(cur.block_loc(), cur.what() + " should have at least 2 objects");
    if (csg.children.empty() && csg.lights.empty())
        cur.warn(cur.block_loc(), cur.what() + " has no objects");
    return std::make_shared<scene::Object>(std::move(obj));
}

void collect_csg_lights(const scene::Object& obj, const scene::Transform& to_world,
                        std::vector<scene::Light>& out) {
    const auto* csg = std::get_if<scene::Csg>(&obj.shape);
    if (!csg) return;
    const scene::Transform world = obj.transform.then(to_world);
    for (const auto& l : csg->lights) {
        if (!l) continue;
        scene::Light light = *l;
        transform_light(light, world);
        out.push_back(std::move(light));
    }
    for (const auto& c : csg->children)
        if (c) collect_csg_lights(*c, world, out);
}

}  // namespace lumen::interp

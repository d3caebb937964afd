// union / merge / intersection / difference: children first, then object modifiers.
// Children keep an empty texture when none was given: the renderer lets them inherit the
// CSG's texture. Light sources inside are kept apart and become scene lights when the CSG is
// placed in the scene. A light_group is a union whose lights light only its members.
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
    csg.is_light_group = cur.what() == "light_group";
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
        if (csg.is_light_group && item.kind == Item::Kind::Keyword &&
            item.keyword == "global_lights") {
            csg.global_lights = cur.optional_bool();
            return true;
        }
        return false;
    };
    read_object_modifiers(cur, obj, modifier,
                          csg.is_light_group ? std::vector<std::string>{"global_lights"}
                                             : std::vector<std::string>{});
    if (csg.children.size() < 2 && csg.op != scene::CsgOp::Union)
        cur.warn(cur.block_loc(), cur.what() + " should have at least 2 objects");
    if (csg.children.empty() && csg.lights.empty())
        cur.warn(cur.block_loc(), cur.what() + " has no objects");
    return std::make_shared<scene::Object>(std::move(obj));
}

scene::ObjectPtr place_csg_lights(const scene::ObjectPtr& obj, const scene::Transform& to_world,
                                  scene::Scene& scene) {
    const auto* csg = obj ? std::get_if<scene::Csg>(&obj->shape) : nullptr;
    if (!csg) return obj;
    const scene::Transform world = obj->transform.then(to_world);
    // Each placement of a light_group is a group of its own: `object { G }` twice gives two.
    // A light in a plain CSG lights the whole scene even inside a group (POV-Ray, probed).
    const uint32_t own = csg->is_light_group ? ++scene.light_groups : 0;
    for (const auto& l : csg->lights) {
        if (!l) continue;
        scene::Light light = *l;
        transform_light(light, world);
        light.group = own;
        scene.lights.push_back(std::move(light));
    }
    std::vector<scene::ObjectPtr> children;
    bool changed = own != 0;
    for (const auto& c : csg->children) {
        children.push_back(place_csg_lights(c, world, scene));
        changed = changed || children.back() != c;
    }
    if (!changed) return obj;  // no light_group inside: the object is shared as it is
    auto placed = std::make_shared<scene::Object>(*obj);
    auto& placed_csg = std::get<scene::Csg>(placed->shape);
    placed_csg.children = std::move(children);
    placed_csg.light_group = own;
    return placed;
}

}  // namespace lumen::interp

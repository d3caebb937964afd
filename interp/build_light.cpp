// light_source { <pos>, colour modifiers } (POV-Ray 3.7's rules). Transforms are gathered
// and applied at the end to the position, point_at, area axes and looks_like object.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

const std::vector<std::string>& light_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v = transform_keywords();
        for (const char* w : {"spotlight", "cylinder", "point_at", "radius", "falloff",
                              "tightness", "parallel", "shadowless", "fade_distance",
                              "fade_power", "area_light", "adaptive", "jitter", "circular",
                              "orient", "area_illumination", "looks_like", "projected_through",
                              "media_interaction", "media_attenuation", "color", "colour"})
            v.push_back(w);
        return v;
    }();
    return k;
}

scene::ObjectPtr single_object(ItemCursor& cur, const BlockValue& block) {
    ItemCursor sub(cur.ctx(), block);
    scene::ObjectPtr obj;
    if (sub.next_is<scene::Unsupported>())
        obj = unsupported_object(sub.next().value.as<scene::Unsupported>());
    else
        obj = sub.expect<scene::ObjectPtr>("", "an object");
    if (!sub.at_end()) sub.fail_unexpected(sub.peek(), {});
    return obj;
}

void read_area_light(ItemCursor& cur, SourceLoc loc, scene::Light& light) {
    scene::AreaLight a = light.area.value_or(scene::AreaLight{});
    a.axis1 = cur.expect_vector("area_light");
    a.axis2 = cur.expect_vector("area_light");
    a.size1 = cur.expect_int("area_light");
    a.size2 = cur.expect_int("area_light");
    if (a.size1 < 1 || a.size2 < 1) cur.fail(loc, "area_light sizes must be at least 1");
    light.area = a;
}

}  // namespace

scene::Light build_light(ItemCursor& cur) {
    scene::Light light;
    bool copied = cur.next_is<std::shared_ptr<const scene::Light>>();
    if (copied) {
        light = *cur.next().value.as<std::shared_ptr<const scene::Light>>();
    } else {
        light.position = cur.expect_vector("");
        if (cur.next_is_colour_start())
            light.colour = cur.expect_colour("").rgb();
    }
    light.loc = cur.block_loc();
    scene::Transform transform;
    // Area modifiers without an area_light are accepted and have no effect (as in POV).
    scene::AreaLight ignored;
    auto area = [&]() -> scene::AreaLight& { return light.area ? *light.area : ignored; };
    while (!cur.at_end()) {
        const Item& item = cur.next();
        scene::Transform t;
        if (read_transform(cur, item, t)) {
            transform = transform.then(t);
            continue;
        }
        if (item.kind == Item::Kind::Value) {
            if (item.value.is<scene::Unsupported>()) {  // photons { } ...
                light.unsupported.push_back(item.value.as<scene::Unsupported>());
            } else if (const BlockValue* b = block_of(item, "photons")) {
                read_light_photons(cur, *b, light);
            } else if (const BlockValue* b = block_of(item, "looks_like")) {
                // Placed at the light, and never shadowing its own light.
                auto obj = std::make_shared<scene::Object>(
                    *transformed(single_object(cur, *b), translation(light.position)));
                obj->no_shadow = true;
                light.looks_like = obj;
            } else if (const BlockValue* b = block_of(item, "projected_through")) {
                light.projected_through = single_object(cur, *b);
            } else if (item.value.is<scene::Colour>()) {
                light.colour = item.value.as<scene::Colour>().rgb();
            } else {
                cur.fail_unexpected(item, light_keywords());
            }
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, light_keywords());
        const std::string& w = item.keyword;
        if (w == "spotlight") light.type = scene::LightType::Spot;
        else if (w == "cylinder") {
            light.type = scene::LightType::Cylinder;
            light.radius = 0.75;
            light.falloff = 1;
        } else if (w == "point_at") light.point_at = cur.expect_vector(w);
        else if (w == "radius") light.radius = cur.expect_float(w);
        else if (w == "falloff") light.falloff = cur.expect_float(w);
        else if (w == "tightness") light.tightness = cur.expect_float(w);
        else if (w == "parallel") light.parallel = cur.optional_bool();
        else if (w == "shadowless") light.shadowless = cur.optional_bool();
        else if (w == "fade_distance") light.fade_distance = cur.expect_float(w);
        else if (w == "fade_power") light.fade_power = cur.expect_float(w);
        else if (w == "area_light") read_area_light(cur, item.loc, light);
        else if (w == "adaptive") area().adaptive = cur.expect_int(w);
        else if (w == "jitter") area().jitter = cur.optional_bool();
        else if (w == "circular") area().circular = cur.optional_bool();
        else if (w == "orient") area().orient = cur.optional_bool();
        else if (w == "area_illumination") light.area_illumination = cur.optional_bool();
        else if (w == "media_interaction") light.media_interaction = cur.optional_bool();
        else if (w == "media_attenuation") light.media_attenuation = cur.optional_bool();
        else if (w == "color" || w == "colour") light.colour = cur.expect_colour(w).rgb();
        else cur.fail_unexpected(item, light_keywords());
    }
    transform_light(light, transform);
    return light;
}

void transform_light(scene::Light& light, const scene::Transform& t) {
    if (t.is_identity()) return;
    light.position = t.point(light.position);
    light.point_at = t.point(light.point_at);
    if (light.area) {
        light.area->axis1 = t.vector(light.area->axis1);
        light.area->axis2 = t.vector(light.area->axis2);
    }
    if (light.looks_like) light.looks_like = transformed(light.looks_like, t);
    if (light.projected_through) light.projected_through = transformed(light.projected_through, t);
}

}  // namespace lumen::interp

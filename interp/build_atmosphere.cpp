// background, fog, rainbow and sky_sphere (POV-Ray 3.7's rules).
#include "interp/build_common.hpp"

#include <optional>

#include <glm/geometric.hpp>

namespace lumen::interp {

scene::Colour build_background(ItemCursor& cur) {
    scene::Colour c = cur.expect_colour("");
    if (!cur.at_end()) cur.fail_unexpected(cur.peek(), {});
    // Without alpha output the background's rgb is premultiplied by its opacity.
    c.r *= 1.0 - c.t;
    c.g *= 1.0 - c.t;
    c.b *= 1.0 - c.t;
    return c;
}

scene::Fog build_fog(ItemCursor& cur) {
    static const std::vector<std::string> keywords = {
        "fog_type", "distance", "color", "colour", "turbulence", "turb_depth", "omega", "lambda",
        "octaves", "fog_offset", "fog_alt", "up", "translate", "rotate", "scale", "matrix",
        "transform"};
    scene::Fog fog;
    if (cur.next_is<std::shared_ptr<const scene::Fog>>())
        fog = *cur.next().value.as<std::shared_ptr<const scene::Fog>>();
    fog.loc = cur.block_loc();
    while (!cur.at_end()) {
        if (cur.next_is_colour_like()) {  // `fog { rgb <...> }` without the colour keyword
            fog.colour = cur.expect_colour("");
            continue;
        }
        const Item& item = cur.next();
        scene::Transform t;
        if (read_transform(cur, item, t)) {
            fog.transform = fog.transform.then(t);
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "fog_type") {
            fog.type = cur.expect_int(w);
            if (fog.type != 1 && fog.type != 2) cur.fail(item.loc, "fog_type must be 1 or 2");
        } else if (w == "distance") fog.distance = cur.expect_float(w);
        else if (w == "color" || w == "colour" || w == "rgb" || w == "rgbf" || w == "rgbt" ||
                 w == "rgbft") {
            fog.colour = cur.expect_colour(w);
        } else if (w == "turbulence") fog.turbulence.amount = cur.expect_vector(w);
        else if (w == "turb_depth") fog.turb_depth = cur.expect_float(w);
        else if (w == "omega") fog.turbulence.omega = single_precision(cur.expect_float(w));
        else if (w == "lambda") fog.turbulence.lambda = single_precision(cur.expect_float(w));
        else if (w == "octaves") fog.turbulence.octaves = cur.expect_int(w);
        else if (w == "fog_offset") fog.offset = cur.expect_float(w);
        else if (w == "fog_alt") fog.alt = cur.expect_float(w);
        else if (w == "up") fog.up = cur.expect_vector(w);
        else cur.fail_unexpected(item, keywords);
    }
    return fog;
}

scene::Rainbow build_rainbow(ItemCursor& cur) {
    static const std::vector<std::string> keywords = {
        "direction", "angle", "width", "distance", "jitter", "up", "arc_angle", "falloff_angle",
        "color_map", "colour_map"};
    scene::Rainbow rainbow;
    if (cur.next_is<std::shared_ptr<const scene::Rainbow>>())
        rainbow = *cur.next().value.as<std::shared_ptr<const scene::Rainbow>>();
    rainbow.loc = cur.block_loc();
    std::optional<double> arc, falloff;
    if (rainbow.arc) arc = rainbow.arc->arc_angle, falloff = rainbow.arc->falloff_angle;
    while (!cur.at_end()) {
        if (cur.next_is<std::shared_ptr<const ColourMapValue>>()) {  // colour_map { } or its identifier
            rainbow.colour_map = cur.next().value.as<std::shared_ptr<const ColourMapValue>>()->entries;
            continue;
        }
        const Item& item = cur.next();
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "direction") rainbow.direction = cur.expect_vector(w);
        else if (w == "angle") rainbow.angle = cur.expect_float(w);
        else if (w == "width") rainbow.width = cur.expect_float(w);
        else if (w == "distance") rainbow.distance = cur.expect_float(w);
        else if (w == "jitter") rainbow.jitter = cur.expect_float(w);
        else if (w == "up") rainbow.up = cur.expect_vector(w);
        else if (w == "arc_angle" || w == "falloff_angle") {
            const double a = cur.expect_float(w);
            // POV-Ray's range check, as each is read.
            if (!(a >= 0 && a <= 360))
                cur.fail(item.loc, "illegal " + w + " in rainbow", "use a value from 0 to 360 degrees");
            (w == "arc_angle" ? arc : falloff) = a;
        } else cur.fail_unexpected(item, keywords);
    }
    // Checked at the end of the block, as POV-Ray does (whether or not the arc is partial).
    if (rainbow.up == glm::dvec3(0)) cur.fail(rainbow.loc, "rainbow's up vector is zero");
    if (glm::length(glm::cross(glm::normalize(rainbow.up), glm::normalize(rainbow.direction))) <
        1e-10)
        cur.fail(rainbow.loc, "rainbow's up and direction vectors are co-linear");
    // Only arc_angle makes a partial arc: falloff_angle alone changes nothing (probed).
    if (arc) {
        if (*arc < falloff.value_or(*arc))
            cur.fail(rainbow.loc, "rainbow arc_angle is smaller than its falloff_angle");
        rainbow.arc = scene::Rainbow::Arc{*arc, falloff.value_or(*arc)};
    }
    return rainbow;
}

scene::SkySphere build_sky_sphere(ItemCursor& cur) {
    static const std::vector<std::string> keywords = {"pigment", "emission", "translate",
                                                      "rotate", "scale", "matrix", "transform"};
    scene::SkySphere sky;
    if (cur.next_is<std::shared_ptr<const scene::SkySphere>>())
        sky = *cur.next().value.as<std::shared_ptr<const scene::SkySphere>>();
    sky.loc = cur.block_loc();
    while (!cur.at_end()) {
        const Item& item = cur.next();
        scene::Transform t;
        if (read_transform(cur, item, t)) {  // pigments are evaluated in the sky's space
            sky.transform = sky.transform.then(t);
        } else if (item.kind == Item::Kind::Value && item.value.is<scene::PigmentPtr>()) {
            sky.pigments.push_back(item.value.as<scene::PigmentPtr>());
        } else if (item.kind == Item::Kind::Keyword && item.keyword == "emission") {
            if (cur.next_is_float()) sky.emission = cur.expect_float("emission");
            else sky.emission = cur.expect_colour("emission").r;
        } else {
            cur.fail_unexpected(item, keywords);
        }
    }
    return sky;
}

}  // namespace lumen::interp

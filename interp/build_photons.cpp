// photons { } blocks: global_settings' (the photon pass), an object's and a light's.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

scene::PhotonToggle toggle(ItemCursor& cur, const std::string& w) {
    return cur.expect_float(w) != 0 ? scene::PhotonToggle::On : scene::PhotonToggle::Off;
}

}  // namespace

scene::PhotonSettings build_global_photons(ItemCursor& cur, std::vector<scene::Unsupported>& unsupported) {
    static const std::vector<std::string> keywords = {
        "spacing", "count", "gather", "media", "jitter", "max_trace_level", "adc_bailout",
        "save_file", "load_file", "autostop", "expand_thresholds", "radius"};
    scene::PhotonSettings p;
    p.loc = cur.block_loc();
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "spacing") {
            p.spacing = cur.expect_float(w);
            if (!(p.spacing > 0)) cur.fail(item.loc, "photons spacing must be above 0");
        } else if (w == "count") {
            p.count = cur.expect_int(w);
            if (p.count < 0) cur.fail(item.loc, "photons count must not be negative");
        } else if (w == "gather") {
            p.gather_min = cur.expect_int(w);
            p.gather_max = cur.expect_int(w);
            if (p.gather_min < 0 || p.gather_max < 0)
                cur.fail(item.loc, "photons gather counts must not be negative");
            if (p.gather_min > p.gather_max)
                cur.fail(item.loc, "photons gather: the minimum is above the maximum");
            if (p.gather_max > 100000)
                cur.fail(item.loc, "photons gather: at most 100000 photons per estimate");
        } else if (w == "media") {
            p.media_steps = cur.expect_int(w);
            if (cur.next_is_float()) p.media_factor = cur.expect_float(w);
            if (p.media_steps < 0) cur.fail(item.loc, "photons media steps must not be negative");
            if (!(p.media_factor > 0)) cur.fail(item.loc, "photons media factor must be above 0");
            if (p.media_steps > 0) p.media_loc = item.loc;
        } else if (w == "jitter") {
            p.jitter = cur.expect_float(w);
        } else if (w == "max_trace_level") {
            p.max_trace_level = std::clamp(cur.expect_int(w), 1, 256);
        } else if (w == "adc_bailout") {
            p.adc_bailout = std::max(0.0, cur.expect_float(w));
        } else if (w == "save_file" || w == "load_file") {
            (w == "save_file" ? p.save_file : p.load_file) = cur.expect_string(w);
            p.file_loc = item.loc;
        } else if (w == "autostop") {
            p.autostop = cur.expect_float(w);
        } else if (w == "expand_thresholds") {
            p.expand_percent = cur.expect_float(w);
            p.expand_min = cur.expect_int(w);
            if (p.expand_percent < 0 || p.expand_min < 0) {
                cur.warn(item.loc, "photons expand_thresholds below 0 are taken as 0");
                p.expand_percent = std::max(0.0, p.expand_percent);
                p.expand_min = std::max(0, p.expand_min);
            }
        } else if (w == "radius") {
            double* fields[] = {&p.radius, &p.radius_mult, &p.media_radius, &p.media_radius_mult};
            for (double* f : fields) {
                if (!cur.next_is_float()) break;
                *f = cur.expect_float(w);
            }
            if (p.radius_mult <= 0) p.radius_mult = 1;
            if (p.media_radius_mult <= 0) p.media_radius_mult = 1;
        } else {
            cur.fail_unexpected(item, keywords);
        }
    }
    // lumen's photon files hold the surface map only.
    if (p.media_steps > 0 && (!p.save_file.empty() || !p.load_file.empty()))
        unsupported.push_back({"photons media with save_file or load_file", p.media_loc});
    return p;
}

void read_object_photons(ItemCursor& cur, const BlockValue& block, scene::Object& obj) {
    static const std::vector<std::string> keywords = {"target", "refraction", "reflection",
                                                      "collect", "pass_through"};
    ItemCursor sub(cur.ctx(), block);
    scene::ObjectPhotons p = obj.photons.value_or(scene::ObjectPhotons{});
    while (!sub.at_end()) {
        const Item& item = sub.next();
        if (item.kind != Item::Kind::Keyword) sub.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "target") {
            p.target_mult = sub.optional_float().value_or(1.0);
            p.target = p.target_mult > 0;
        } else if (w == "refraction") p.refraction = toggle(sub, w);
        else if (w == "reflection") p.reflection = toggle(sub, w);
        else if (w == "collect") p.collect = sub.optional_bool();
        else if (w == "pass_through") p.pass_through = sub.optional_bool();
        else sub.fail_unexpected(item, keywords);
    }
    // POV-Ray: a target passing photons straight through cannot also refract them.
    if (p.target && p.pass_through && p.refraction == scene::PhotonToggle::On) {
        cur.warn(block.loc, "photons: a pass_through target does not refract; refraction is off");
        p.refraction = scene::PhotonToggle::Off;
    }
    obj.photons = p;
}

void read_light_photons(ItemCursor& cur, const BlockValue& block, scene::Light& light) {
    static const std::vector<std::string> keywords = {"refraction", "reflection", "area_light"};
    ItemCursor sub(cur.ctx(), block);
    while (!sub.at_end()) {
        const Item& item = sub.next();
        if (item.kind != Item::Kind::Keyword) sub.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "refraction") light.photons.refraction = toggle(sub, w);
        else if (w == "reflection") light.photons.reflection = toggle(sub, w);
        else if (w == "area_light") light.photons.area_light = sub.optional_bool();
        else sub.fail_unexpected(item, keywords);
    }
}

}  // namespace lumen::interp

// interior { [Ident] ior caustics dispersion dispersion_samples fade_* media }
#include "interp/build_common.hpp"

namespace lumen::interp {

scene::Interior build_interior(ItemCursor& cur) {
    static const std::vector<std::string> keywords = {
        "ior", "caustics", "dispersion", "dispersion_samples", "fade_distance", "fade_power",
        "fade_color", "fade_colour", "media"};
    scene::Interior in;
    if (cur.next_is<std::shared_ptr<const scene::Interior>>())
        in = *cur.next().value.as<std::shared_ptr<const scene::Interior>>();
    in.loc = cur.block_loc();
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (item.kind == Item::Kind::Value && item.value.is<scene::MediaPtr>()) {
            in.media.push_back(item.value.as<scene::MediaPtr>());
            continue;
        }
        scene::Transform t;
        if (read_transform(cur, item, t)) {  // moves the media's densities
            for (auto& m : in.media) m = transformed(m, t);
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "ior") in.ior = cur.expect_float(w);
        else if (w == "caustics") in.caustics = cur.expect_float(w);
        else if (w == "dispersion") in.dispersion = cur.expect_float(w);
        else if (w == "dispersion_samples") in.dispersion_samples = cur.expect_int(w);
        else if (w == "fade_distance") in.fade_distance = cur.expect_float(w);
        else if (w == "fade_power") in.fade_power = cur.expect_float(w);
        else if (w == "fade_color" || w == "fade_colour") in.fade_colour = cur.expect_colour(w).rgb();
        else cur.fail_unexpected(item, keywords);
    }
    return in;
}

}  // namespace lumen::interp

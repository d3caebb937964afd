// global_settings { } and its radiosity { } block.
#include <algorithm>

#include "interp/build_common.hpp"
#include "noise/noise.hpp"

namespace lumen::interp {

namespace {

void read_radiosity(BuildContext& ctx, const BlockValue& block, scene::RadiositySettings& r) {
    static const std::vector<std::string> keywords = {
        "count", "error_bound", "recursion_limit", "nearest_count", "pretrace_start",
        "pretrace_end", "low_error_factor", "gray_threshold", "minimum_reuse", "maximum_reuse",
        "brightness", "adc_bailout", "always_sample", "normal", "media", "max_sample",
        "importance", "subsurface"};
    ItemCursor cur(ctx, block);
    r.loc = block.loc;
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "count") {
            r.count = cur.expect_int(w);
            if (cur.next_is_float()) r.count_pool = cur.expect_int(w);
        } else if (w == "error_bound") r.error_bound = cur.expect_float(w);
        else if (w == "recursion_limit") r.recursion_limit = cur.expect_int(w);
        else if (w == "nearest_count") {
            r.nearest_count = cur.expect_int(w);
            cur.optional_float();  // adaptive pretrace count: not modelled
        } else if (w == "pretrace_start") r.pretrace_start = cur.expect_float(w);
        else if (w == "pretrace_end") r.pretrace_end = cur.expect_float(w);
        else if (w == "low_error_factor") r.low_error_factor = cur.expect_float(w);
        else if (w == "gray_threshold") r.gray_threshold = cur.expect_float(w);
        else if (w == "minimum_reuse") r.minimum_reuse = cur.expect_float(w);
        else if (w == "maximum_reuse") r.maximum_reuse = cur.expect_float(w);
        else if (w == "brightness") r.brightness = cur.expect_float(w);
        else if (w == "adc_bailout") r.adc_bailout = cur.expect_float(w);
        else if (w == "always_sample") r.always_sample = cur.optional_bool();
        else if (w == "normal") r.normal = cur.optional_bool();
        else if (w == "media") r.media = cur.optional_bool();
        else if (w == "max_sample") r.max_sample = cur.expect_float(w);
        else if (w == "importance") cur.expect_float(w);
        else if (w == "subsurface") cur.optional_bool();
        else cur.fail_unexpected(item, keywords);
        // lumen's patch radiosity has no place for these (README "Radiosity").
        const bool ignored = w == "importance" || w == "max_sample" ||
                             (w == "normal" && r.normal) || (w == "media" && r.media) ||
                             w == "subsurface";
        if (ignored) cur.warn(item.loc, "radiosity " + w + " is not supported and has no effect");
    }
}

}  // namespace

void apply_global_settings(ItemCursor& cur, scene::GlobalSettings& g) {
    static const std::vector<std::string> keywords = {
        "assumed_gamma", "max_trace_level", "adc_bailout", "ambient_light", "irid_wavelength",
        "noise_generator", "number_of_waves", "charset", "hf_gray_16", "max_intersections",
        "radiosity", "photons", "subsurface", "mm_per_unit"};
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (item.kind == Item::Kind::Value) {
            if (item.value.is<scene::Unsupported>()) {  // photons { }, subsurface { }
                g.unsupported.push_back(item.value.as<scene::Unsupported>());
            } else if (const BlockValue* b = block_of(item, "photons")) {
                ItemCursor sub(cur.ctx(), *b);
                g.photons = build_global_photons(sub, g.unsupported);
            } else if (const BlockValue* b = block_of(item, "radiosity")) {
                scene::RadiositySettings r = g.radiosity.value_or(scene::RadiositySettings{});
                read_radiosity(cur.ctx(), *b, r);
                g.radiosity = r;
            } else {
                cur.fail_unexpected(item, keywords);
            }
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        if (w == "assumed_gamma") {
            double gamma = 2.2;  // `assumed_gamma srgb`
            if (!cur.accept_keyword("srgb")) gamma = cur.expect_float(w);
            if (g.assumed_gamma) cur.warn(item.loc, "assumed_gamma given twice: the first counts");
            else g.assumed_gamma = cur.ctx().assumed_gamma = gamma;
        } else if (w == "max_trace_level") {
            g.max_trace_level = std::clamp(cur.expect_int(w), 1, 256);
        } else if (w == "adc_bailout") g.adc_bailout = cur.expect_float(w);
        else if (w == "ambient_light") g.ambient_light = cur.expect_colour(w).rgb();
        else if (w == "irid_wavelength") g.irid_wavelength = cur.expect_colour(w).rgb();
        else if (w == "noise_generator") {
            g.noise_generator = cur.expect_int(w);
            if (g.noise_generator < 1 || g.noise_generator > 3)
                cur.fail(item.loc, "noise_generator must be 1, 2 or 3");
            cur.ctx().noise_generator_given = true;
            cur.ctx().noise_generator_read = g.noise_generator;
        } else if (w == "number_of_waves") {
            g.number_of_waves = cur.expect_int(w);
            if (g.number_of_waves > noise::kMaxWaves)
                g.unsupported.push_back({"number_of_waves above " +
                                             std::to_string(noise::kMaxWaves), item.loc});
        }
        else if (w == "charset") {
            if (cur.accept_keyword("ascii")) cur.ctx().utf8_strings = false;
            else if (cur.accept_keyword("utf8") || cur.accept_keyword("sys"))
                cur.ctx().utf8_strings = true;
            else cur.fail_expected("ascii, utf8 or sys", w);
        } else if (w == "hf_gray_16") cur.optional_bool();
        else if (w == "max_intersections") cur.expect_float(w);
        else if (w == "mm_per_unit") {
            cur.expect_float(w);
            g.unsupported.push_back({"subsurface", item.loc});
        } else cur.fail_unexpected(item, keywords);
    }
}

}  // namespace lumen::interp

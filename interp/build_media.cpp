// media { [Ident] method intervals samples confidence variance ratio jitter aa_level
// aa_threshold absorption emission scattering { type, colour [eccentricity] [extinction] }
// density { } ... collect transforms } and density { pigment body }, with POV-Ray 3.7's
// defaults and checks.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// Bounds on the work one media sample may ask for (POV-Ray has none; a typo should not hang).
constexpr int kMaxIntervals = 1000, kMaxSamples = 100000, kMaxAaLevel = 16;

void read_scattering(ItemCursor& cur, scene::Media& m) {
    const SourceLoc loc = cur.next_loc();
    const int type = cur.expect_int("scattering");
    if (type < 1 || type > 5)
        cur.warn(loc, "unknown scattering type " + std::to_string(type) + ": isotropic is used");
    m.scattering_type = type < 1 || type > 5 ? 1 : type;
    m.scattering = cur.expect_colour("scattering").rgb();
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (item.kind == Item::Kind::Keyword && item.keyword == "eccentricity") {
            if (m.scattering_type != 5)
                cur.fail(item.loc, "eccentricity belongs to scattering type 5 (Henyey-Greenstein)");
            m.eccentricity = cur.expect_float("eccentricity");
        } else if (item.kind == Item::Kind::Keyword && item.keyword == "extinction") {
            m.extinction = cur.expect_float("extinction");
        } else {
            cur.fail_unexpected(item, {"eccentricity", "extinction"});
        }
    }
}

}  // namespace

scene::PigmentPtr build_density(ItemCursor& cur) { return build_pigment(cur); }

scene::MediaPtr transformed(const scene::MediaPtr& media, const scene::Transform& t) {
    if (!media || media->densities.empty()) return media;
    auto m = std::make_shared<scene::Media>(*media);
    for (auto& d : m->densities) d = transformed(d, t);
    return m;
}

scene::MediaPtr build_media(ItemCursor& cur) {
    static const std::vector<std::string> keywords = {
        "method", "intervals", "samples", "confidence", "variance", "ratio", "jitter",
        "aa_level", "aa_threshold", "absorption", "emission", "scattering", "density", "collect"};
    scene::Media m;
    if (cur.next_is<scene::MediaPtr>()) {
        m = *cur.next().value.as<scene::MediaPtr>();
    } else if (cur.ctx().language_version < 3.5) {
        m.method = 1, m.intervals = 10, m.samples_min = m.samples_max = 1;
    }
    m.loc = cur.block_loc();
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (item.kind == Item::Kind::Value && item.value.is<scene::PigmentPtr>()) {  // density { }
            m.densities.insert(m.densities.begin(), item.value.as<scene::PigmentPtr>());
            continue;
        }
        if (const BlockValue* b = block_of(item, "scattering")) {
            ItemCursor sub(cur.ctx(), *b);
            read_scattering(sub, m);
            continue;
        }
        scene::Transform t;
        if (read_transform(cur, item, t)) {  // moves the densities written so far
            for (auto& d : m.densities) d = transformed(d, t);
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, keywords);
        const std::string& w = item.keyword;
        const SourceLoc at = cur.next_loc();
        if (w == "method") {
            m.method = cur.expect_int(w);
            if (m.method < 1 || m.method > 3) cur.fail(at, "media method must be 1, 2 or 3");
        } else if (w == "intervals") {
            m.intervals = cur.expect_int(w);
            if (m.intervals < 1) cur.fail(at, "media intervals must be at least 1");
            if (m.intervals > kMaxIntervals)
                cur.fail(at, "lumen takes at most " + std::to_string(kMaxIntervals) + " media intervals");
        } else if (w == "samples") {
            m.samples_min = cur.expect_int(w);
            m.samples_max = cur.next_is_float() ? cur.expect_int(w) : m.samples_min;
            if (m.samples_min < 1) cur.fail(at, "media samples must be at least 1");
            if (m.samples_max < m.samples_min)
                cur.fail(at, "the media's maximum samples are fewer than its minimum");
            if (m.samples_max > kMaxSamples)
                cur.fail(at, "lumen takes at most " + std::to_string(kMaxSamples) + " media samples");
        } else if (w == "confidence") {
            m.confidence = cur.expect_float(w);
            if (m.confidence < 0 || m.confidence >= 1) cur.fail(at, "media confidence must be in [0, 1)");
        } else if (w == "variance") {
            m.variance = cur.expect_float(w);
        } else if (w == "ratio") {
            m.ratio = cur.expect_float(w);
        } else if (w == "jitter") {
            m.jitter = cur.expect_float(w);
        } else if (w == "aa_level") {
            m.aa_level = cur.expect_int(w);
            if (m.aa_level < 1) cur.fail(at, "media aa_level must be at least 1");
            if (m.aa_level > kMaxAaLevel)  // each level may double a sub-step's samples
                cur.fail(at, "lumen takes a media aa_level of at most " + std::to_string(kMaxAaLevel));
        } else if (w == "aa_threshold") {
            m.aa_threshold = cur.expect_float(w);
            if (!(m.aa_threshold > 0)) cur.fail(at, "media aa_threshold must be positive");
        } else if (w == "absorption") {
            m.absorption = cur.expect_colour(w).rgb();
        } else if (w == "emission") {
            m.emission = cur.expect_colour(w).rgb();
        } else if (w == "collect") {
            m.collect = cur.optional_bool();
        } else {
            cur.fail_unexpected(item, keywords);
        }
    }
    return std::make_shared<scene::Media>(std::move(m));
}

}  // namespace lumen::interp

// warp { turbulence | repeat | black_hole | cylindrical | spherical | toroidal | planar |
// cubic ... }: one step of the pattern's ordered transforms and warps. Warps are read and kept
// so that the noise issue only adds their evaluation; until then the pattern is reported
// unsupported ('warp'). As in POV-Ray 3.7, a warp block holds exactly one warp type, written
// first, followed by that type's own modifiers.
#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

using Shape = scene::warp::Mapping::Shape;

// Reads the warp type's modifiers up to the block's end: `read(word)` takes one and returns
// false for a word the type does not have, which is then an error listing `known`.
template <class Read>
void read_options(ItemCursor& cur, const std::vector<std::string>& known, const Read& read) {
    while (!cur.at_end()) {
        const Item& it = cur.next();
        if (it.kind != Item::Kind::Keyword || !read(it.keyword)) cur.fail_unexpected(it, known);
    }
}

scene::warp::Turbulence read_turbulence(ItemCursor& cur, SourceLoc loc) {
    scene::warp::Turbulence t;
    t.loc = loc;
    t.amount = cur.expect_vector("turbulence");
    read_options(cur, {"octaves", "omega", "lambda"}, [&](const std::string& w) {
        if (w == "octaves") t.octaves = cur.expect_int(w);
        else if (w == "omega") t.omega = single_precision(cur.expect_float(w));
        else if (w == "lambda") t.lambda = single_precision(cur.expect_float(w));
        else return false;
        return true;
    });
    return t;
}

scene::warp::Repeat read_repeat(ItemCursor& cur, SourceLoc loc) {
    scene::warp::Repeat r;
    r.loc = loc;
    r.direction = cur.expect_vector("repeat");
    const int axes = (r.direction.x != 0) + (r.direction.y != 0) + (r.direction.z != 0);
    if (axes == 0) cur.fail(loc, "no axis given in repeat");
    if (axes > 1) cur.fail(loc, "repeat works along one axis only");
    read_options(cur, {"offset", "flip"}, [&](const std::string& w) {
        if (w == "offset") r.offset = cur.expect_vector(w);
        else if (w == "flip") r.flip = cur.expect_vector(w);
        else return false;
        return true;
    });
    return r;
}

scene::warp::BlackHole read_black_hole(ItemCursor& cur, SourceLoc loc) {
    scene::warp::BlackHole b;
    b.loc = loc;
    b.centre = cur.expect_vector("black_hole");
    b.radius = cur.expect_float("black_hole");
    read_options(cur, {"falloff", "strength", "repeat", "turbulence", "inverse"},
                 [&](const std::string& w) {
                     if (w == "falloff") b.falloff = cur.expect_float(w);
                     else if (w == "strength") b.strength = cur.expect_float(w);
                     else if (w == "repeat") b.repeat = cur.expect_vector(w);
                     else if (w == "turbulence") b.turbulence = cur.expect_vector(w);
                     else if (w == "inverse") b.inverse = !b.inverse;
                     else return false;
                     return true;
                 });
    return b;
}

scene::warp::Mapping read_mapping(ItemCursor& cur, Shape shape, SourceLoc loc) {
    scene::warp::Mapping m;
    m.shape = shape;
    m.loc = loc;
    // POV: planar and cubic take no modifiers, only toroidal a major_radius.
    const bool oriented = shape != Shape::Planar && shape != Shape::Cubic;
    std::vector<std::string> known;
    if (oriented) known = {"orientation", "dist_exp"};
    if (shape == Shape::Toroidal) known.push_back("major_radius");
    read_options(cur, known, [&](const std::string& w) {
        if (w == "orientation" && oriented) m.orientation = cur.expect_vector(w);
        else if (w == "dist_exp" && oriented) m.dist_exp = cur.expect_float(w);
        else if (w == "major_radius" && shape == Shape::Toroidal) m.major_radius = cur.expect_float(w);
        else return false;
        return true;
    });
    return m;
}

const std::pair<const char*, Shape> kMappings[] = {
    {"cylindrical", Shape::Cylindrical}, {"spherical", Shape::Spherical},
    {"toroidal", Shape::Toroidal},       {"planar", Shape::Planar},
    {"cubic", Shape::Cubic}};

scene::PatternStep read_warp_step(ItemCursor& cur) {
    const std::vector<std::string> types = {"turbulence", "repeat",  "black_hole", "cylindrical",
                                            "spherical",  "toroidal", "planar",    "cubic"};
    if (cur.at_end()) cur.fail_expected("a warp type", "");
    const Item& it = cur.next();
    const std::string w = it.kind == Item::Kind::Keyword ? it.keyword : "";
    if (w == "turbulence") return read_turbulence(cur, it.loc);
    if (w == "repeat") return read_repeat(cur, it.loc);
    if (w == "black_hole") return read_black_hole(cur, it.loc);
    for (const auto& [word, shape] : kMappings)
        if (w == word) return read_mapping(cur, shape, it.loc);
    cur.fail_unexpected(it, types);
}

}  // namespace

void read_warp(ItemCursor& cur, const BlockValue& block, scene::Pattern& pattern) {
    ItemCursor sub(cur.ctx(), block);
    scene::PatternStep step = read_warp_step(sub);
    const bool rendered = std::holds_alternative<scene::warp::Turbulence>(step);
    pattern.steps.steps.push_back(std::move(step));
    if (!rendered) mark_unsupported(pattern, "warp", block.loc);  // the warps issue's
}

}  // namespace lumen::interp

// The pattern table as the reader sees it: keywords, list forms, kind modifiers, the ordered
// transforms and warps, and what is reported unsupported.
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

using BuildPattern = BuildTest;
namespace pattern = scene::pattern;

// What each keyword needs after it to form a valid pigment.
std::string pigment_text(std::string_view keyword) {
    std::string body = pattern_with_arguments(keyword);
    if (keyword == "average") body += " pigment_map { [1 rgb 1] }";
    return "sphere { 0, 1 pigment { " + body + " } }";
}

TEST_F(BuildPattern, EveryTableKeywordReadsAsItsKind) {
    int read = 0;
    for (const scene::PatternInfo& row : scene::kPatternTable) {
        // Plain has no keyword; function { }, object { } and pigment_pattern { } patterns are
        // blocks, not words.
        if (row.keyword.empty() || row.keyword == "function" || row.keyword == "object" ||
            row.keyword == "pigment_pattern")
            continue;
        const scene::Texture t = texture_of(pigment_text(row.keyword));
        EXPECT_EQ(t.pigment->pattern.type(), row.type) << row.keyword;
        // pavement's default layout (3 sides) is not modelled yet: its own test below.
        if (row.keyword == "pavement") {
            ++read;
            continue;
        }
        EXPECT_EQ(t.pigment->pattern.unsupported.has_value(), !row.rendered) << row.keyword;
        if (!row.rendered) {
            EXPECT_EQ(t.pigment->pattern.unsupported->feature,
                      "pattern '" + std::string(row.keyword) + "'");
        }
        ++read;
    }
    EXPECT_EQ(read, int(std::size(scene::kPatternTable)) - 4);
}

TEST_F(BuildPattern, DiscreteCountsAndListForms) {
    EXPECT_EQ(scene::discrete_entries(scene::PatternType::Checker), 2);
    EXPECT_EQ(scene::discrete_entries(scene::PatternType::Brick), 2);
    EXPECT_EQ(scene::discrete_entries(scene::PatternType::Hexagon), 3);
    EXPECT_EQ(scene::discrete_entries(scene::PatternType::Square), 4);
    EXPECT_EQ(scene::discrete_entries(scene::PatternType::Triangular), 6);
    EXPECT_EQ(scene::discrete_entries(scene::PatternType::Gradient), 0);
    for (const scene::PatternInfo& row : scene::kPatternTable) {
        if (row.entries == 0 || row.keyword == "object") continue;  // a block: below
        std::string list;
        for (int i = 0; i < row.entries; ++i) list += (i ? ", rgb " : " rgb ") + std::to_string(i);
        const scene::Texture t =
            texture_of("sphere { 0, 1 pigment { " + std::string(row.keyword) + list + " } }");
        ASSERT_EQ(int(t.pigment->colour_map.size()), row.entries) << row.keyword;
        EXPECT_TRUE(t.pigment->list_form);
        for (int i = 0; i < row.entries; ++i) {
            EXPECT_DOUBLE_EQ(t.pigment->colour_map[i].value, i);
            EXPECT_DOUBLE_EQ(t.pigment->colour_map[i].item.r, i);
        }
    }
}

TEST_F(BuildPattern, KindParametersGoIntoTheKind) {
    const scene::Texture b =
        texture_of("sphere { 0, 1 pigment { brick brick_size <1,2,3> mortar 0.1 } }");
    const auto& brick = std::get<pattern::Brick>(b.pigment->pattern.kind);
    expect_vec(brick.size, {1, 2, 3});
    EXPECT_DOUBLE_EQ(brick.mortar, 0.1);
    const scene::Texture c = texture_of(
        "sphere { 0, 1 pigment { crackle metric 1 form <1,0,0> offset 0.2 solid } }");
    const auto& crackle = std::get<pattern::Crackle>(c.pigment->pattern.kind);
    EXPECT_DOUBLE_EQ(crackle.metric, 1);
    expect_vec(crackle.form, {1, 0, 0});
    EXPECT_DOUBLE_EQ(crackle.offset, 0.2);
    EXPECT_TRUE(crackle.solid);
    const scene::Texture m =
        texture_of("sphere { 0, 1 pigment { mandel 25 exponent 3.7 interior 1, 0.5 } }");
    const auto& mandel = std::get<pattern::Mandel>(m.pigment->pattern.kind);
    EXPECT_EQ(mandel.iterations, 25);
    EXPECT_EQ(mandel.exponent, 3);  // truncated, as POV-Ray does
    EXPECT_DOUBLE_EQ(mandel.interior.y, 0.5);
}

// The fractals' arguments: julia's constant, magnet's type and form; exponents outside
// 2..33 fall back to 2 as in POV-Ray.
TEST_F(BuildPattern, FractalArguments) {
    const auto kind = [&](const std::string& p) {
        return texture_of("sphere { 0, 1 pigment { " + p + " } }").pigment->pattern.kind;
    };
    const auto julia = std::get<pattern::Julia>(kind("julia <0.3, -0.2>, 40"));
    EXPECT_DOUBLE_EQ(julia.c.x, 0.3);
    EXPECT_DOUBLE_EQ(julia.c.y, -0.2);
    EXPECT_EQ(julia.iterations, 40);
    const auto magnet = std::get<pattern::Magnet>(kind("magnet 2 julia <0.1, 0.2> 12"));
    EXPECT_EQ(magnet.type, 2);
    EXPECT_TRUE(magnet.julia);
    EXPECT_EQ(magnet.iterations, 12);
    EXPECT_FALSE(std::get<pattern::Magnet>(kind("magnet 1 mandel 9")).julia);
    EXPECT_EQ(std::get<pattern::Mandel>(kind("mandel 9 exponent 40")).exponent, 2);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { magnet 3 mandel 9 } }"), "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { magnet 1 9 } }"), "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { julia <1, 2, 3>, 9 } }"), "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { mandel } }"), "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { magnet 1 mandel 9 exponent 3 } }"), "no error");
}

// slope's two forms, tiling's number (1..27), quilted's
// skipped frequency, and the voxels of a df3 file found beside the scene.
TEST_F(BuildPattern, SlopeTilingQuiltedAndDensityFile) {
    const auto pattern = [&](const std::string& p) {
        return texture_of("sphere { 0, 1 pigment { " + p + " } }").pigment->pattern;
    };
    const auto simple = std::get<pattern::Slope>(pattern("slope <0, 2, 0>").kind);
    expect_vec(simple.direction, {0, 1, 0});
    EXPECT_DOUBLE_EQ(simple.length, 2);
    const auto full = std::get<pattern::Slope>(
        pattern("slope { point_at <1, 2, 3>, 0.2, 0.8 altitude <0, 0, 3>, 1, 2 }").kind);
    EXPECT_TRUE(full.point_at);
    expect_vec(full.direction, {1, 2, 3});
    EXPECT_DOUBLE_EQ(full.range.y, 0.8);
    expect_vec(full.altitude, {0, 0, 1});
    EXPECT_DOUBLE_EQ(full.altitude_length, 3);
    EXPECT_DOUBLE_EQ(full.altitude_range.x, 1);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { slope { y extra } } }"), "no error");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { tiling 28 } }"),
              "t.pov:1:25: error: tiling number must be between 1 and 27");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { tiling 0 } }"), "no error");
    EXPECT_EQ(std::get<pattern::Tiling>(pattern("tiling 24").kind).type, 24);
    EXPECT_EQ(std::get<pattern::Tiling>(pattern("tiling 2.7").kind).type, 2);  // POV's byte
    EXPECT_EQ(std::get<pattern::Tiling>(pattern("tiling 258").kind).type, 2);
    EXPECT_EQ(std::get<pattern::Tiling>(pattern("tiling -254").kind).type, 2);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { tiling 256 } }"), "no error");
    EXPECT_FALSE(pattern("tiling 7").unsupported);
    EXPECT_FALSE(pattern("tiling 26").unsupported);  // the Penrose tilings render
    EXPECT_EQ(std::get<pattern::Tiling>(pattern("tiling 27").kind).type, 27);
    // pavement: POV's bytes and ranges, checked once the block is read (measured on povray)
    const auto pave = std::get<pattern::Pavement>(pattern("pavement").kind);
    EXPECT_EQ(pave.sides, 3);
    EXPECT_EQ(pave.tiles, 1);
    EXPECT_EQ(pave.number, 1);
    const auto p4 = std::get<pattern::Pavement>(
        pattern("pavement number_of_sides 260 number_of_tiles 6.9 pattern 35 exterior 5 "
                "interior 7 form 9").kind);
    EXPECT_EQ(p4.sides, 4);
    EXPECT_EQ(p4.tiles, 6);
    EXPECT_EQ(p4.number, 35);
    EXPECT_EQ(p4.exterior, 2);
    EXPECT_EQ(p4.interior, 1);
    EXPECT_EQ(p4.form, 1);
    // Every layout renders: triangles (the default), squares and hexagons.
    EXPECT_FALSE(pattern("pavement").unsupported);
    EXPECT_FALSE(pattern("pavement number_of_sides 4").unsupported);
    EXPECT_FALSE(pattern("pavement number_of_sides 4 number_of_tiles 2 form 2").unsupported);
    EXPECT_FALSE(pattern("pavement number_of_sides 4 number_of_tiles 6 pattern 35").unsupported);
    EXPECT_FALSE(pattern("pavement number_of_tiles 6 pattern 12").unsupported);
    EXPECT_FALSE(pattern("pavement number_of_sides 6 number_of_tiles 5 pattern 22").unsupported);
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { pavement number_of_sides 5 } }"),
              "t.pov:1:50: error: number_of_sides of pavement must be 3, 4 or 6");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { pavement number_of_sides 6 number_of_tiles 6 } }"),
              "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { pavement number_of_tiles 4 pattern 4 } }"),
              "no error");  // 3 sides, 4 tiles: 3 layouts
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { pavement number_of_sides 4 number_of_tiles 4 "
                       "pattern 5 } }"),
              "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { gradient x pattern 2 } }"), "no error");
    EXPECT_DOUBLE_EQ(pattern("quilted").frequency, 0);
    EXPECT_DOUBLE_EQ(pattern("quilted frequency 2").frequency, 2);
    const auto df3 = std::get<pattern::DensityFile>(
        pattern(std::string("density_file df3 \"") + LUMEN_SOURCE_DIR +
                "/tests/patterns/grid16.df3\" interpolate 1").kind);
    EXPECT_EQ(df3.interpolate, 1);
    ASSERT_TRUE(df3.grid);
    EXPECT_EQ(df3.grid->nx * df3.grid->ny * df3.grid->nz, 60);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { density_file df3 \"no-such.df3\" } }")
                  .find("cannot find density file"),
              std::string::npos);
}

// POV-Ray 3.7 refuses a kind's modifier on another kind; lumen too, rather than drop it.
TEST_F(BuildPattern, ModifiersOfOtherKindsAreErrors) {
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { gradient x metric 2 } }"),
              "t.pov:1:36: error: 'metric' can only be used in a facets or crackle pattern");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { checker mortar 0.2 } }"),
              "t.pov:1:33: error: 'mortar' can only be used in a brick pattern");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo control0 1 } }"),
              "t.pov:1:30: error: 'control0' can only be used in a quilted pattern");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { gradient x accuracy 0.1 } }"), "no error");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo noise_generator 4 } }"),
              "t.pov:1:30: error: noise_generator must be 0, 1, 2 or 3");
    EXPECT_EQ(texture_of("sphere { 0, 1 pigment { bozo noise_generator 3 } }")
                  .pigment->pattern.noise_generator,
              3);
}

// Transforms compose while nothing comes between them; the classic turbulence goes first
// wherever it is written, and warps stay where they are written.
TEST_F(BuildPattern, StepsInTheOrderPovAppliesThem) {
    const scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { gradient x scale 2 turbulence 0.5 translate x "
        "warp { repeat x offset y } rotate y*90 octaves 3 } }");
    const auto& steps = t.pigment->pattern.steps.steps;
    ASSERT_EQ(steps.size(), 4u);
    const auto& turb = std::get<scene::warp::ClassicTurbulence>(steps[0]);
    expect_vec(turb.amount, {0.5, 0.5, 0.5});
    EXPECT_EQ(turb.octaves, 3);
    expect_vec(std::get<scene::Transform>(steps[1]).point({1, 1, 1}), {3, 2, 2});
    const auto& repeat = std::get<scene::warp::Repeat>(steps[2]);
    expect_vec(repeat.direction, {1, 0, 0});
    expect_vec(repeat.offset, {0, 1, 0});
    expect_vec(std::get<scene::Transform>(steps[3]).point({1, 0, 0}), {0, 0, -1});
    EXPECT_FALSE(t.pigment->pattern.unsupported);  // every step renders
}

// A pigment's transforms written outside the pattern join the same list.
TEST_F(BuildPattern, ObjectTransformsJoinTheSteps) {
    const scene::ObjectPtr o = first_object(
        "sphere { 0, 1 pigment { checker warp { planar } scale 2 } translate x }");
    const auto& steps = o->texture[0]->pigment->pattern.steps.steps;
    ASSERT_EQ(steps.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<scene::warp::Mapping>(steps[0]));
    expect_vec(std::get<scene::Transform>(steps[1]).point({1, 1, 1}), {3, 2, 2});
}

// Every warp type is read; only warp turbulence (the noise issue's) is reported unsupported.
TEST_F(BuildPattern, EveryWarpTypeIsRead) {
    for (const char* warp :
         {"repeat x offset y flip x", "black_hole 0, 1 falloff 2 strength 1 turbulence 0.1 inverse",
          "black_hole <1, 1, 0>, 0.5 repeat <2, 2, 0> turbulence 0.2 type 1",
          "cylindrical orientation y dist_exp 1", "spherical", "toroidal major_radius 2", "planar",
          "planar y, 0.5", "cubic"}) {
        const scene::Scene s =
            run(std::string("sphere { 0, 1 pigment { checker warp { ") + warp + " } } }");
        EXPECT_TRUE(s.unsupported.empty()) << warp;
    }
    const scene::Scene turbulence = run(
        "sphere { 0, 1 pigment { checker warp { turbulence 0.2 octaves 2 omega 0.4 lambda 2.5 } } }");
    EXPECT_TRUE(turbulence.unsupported.empty());
    EXPECT_NE(error_of("sphere { 0, 1 pigment { checker warp { } } }").find("expected a warp type"),
              std::string::npos);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { checker warp { turbulence 0.2 repeat x } } }"),
              "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { checker warp { planar orientation y } } }"),
              "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { checker warp { planar y } } }"), "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { checker warp { repeat x+y } } }"), "no error");
    EXPECT_NE(error_of("sphere { 0, 1 pigment { checker warp { cylindrical orientation 0 } } }"),
              "no error");
}

// The warps' own arguments as POV-Ray keeps them: planar's orientation and offset, a second
// `inverse` that leaves the hole inverted, and a repeated hole raised into its cell.
TEST_F(BuildPattern, WarpParameters) {
    const scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { checker warp { planar <0, 2, 0>, 0.5 } "
        "warp { black_hole <0.1, 0, 0>, 0.5 repeat <1, 0, 0> turbulence 0.2 inverse inverse } } }");
    const auto& steps = t.pigment->pattern.steps.steps;
    ASSERT_EQ(steps.size(), 2u);
    const auto& planar = std::get<scene::warp::Mapping>(steps[0]);
    expect_vec(planar.orientation, {0, 1, 0});
    EXPECT_DOUBLE_EQ(planar.offset, 0.5);
    const auto& hole = std::get<scene::warp::BlackHole>(steps[1]);
    EXPECT_TRUE(hole.inverse);
    expect_vec(hole.centre, {0.5, 0, 0});  // raised to the radius
    expect_vec(hole.repeat, {1.2, 0, 0});  // raised to centre + radius + turbulence
}

// A normal keeps what it is given.
TEST_F(BuildPattern, NormalModifiersAreKept) {
    const scene::Texture t = texture_of(
        "sphere { 0, 1 normal { checker normal { bumps } normal { dents } accuracy 0.1 "
        "no_bump_scale } }");
    EXPECT_EQ(t.normal->accuracy, double(0.1f));  // single precision, as in POV
    EXPECT_TRUE(t.normal->no_bump_scale);
    ASSERT_EQ(t.normal->normal_map.size(), 2u);
    EXPECT_DOUBLE_EQ(t.normal->normal_map[1].value, 1);
    EXPECT_EQ(t.normal->normal_map[1].item->pattern.type(), scene::PatternType::Dents);
}

// Kinds lumen does not render (facets in a pigment) mark the pattern they stand in; the
// pattern blocks it builds (slope { }, pigment_pattern { }) report what they hold.
TEST_F(BuildPattern, UnrenderedKindsMarkThePattern) {
    const scene::Scene s = run(
        "sphere { 0, 1 pigment { facets } }\n"
        "sphere { 0, 1 texture { slope { -z altitude z } texture_map { [0 pigment { rgb 1 }] } } }\n"
        "sphere { 0, 1 pigment { pigment_pattern { facets } } }");
    ASSERT_EQ(s.unsupported.size(), 2u);
    EXPECT_EQ(s.unsupported[0].feature, "pattern 'facets'");
    EXPECT_EQ(s.unsupported[1].feature, "pattern 'facets'");
    EXPECT_EQ(s.unsupported[1].loc.line, 3u);
}

// `object { OBJ A, B }` keeps the object and reads the list entries after it, in pigments,
// textures and normals; the object's own unsupported features are reported.
TEST_F(BuildPattern, ObjectPatternKeepsItsObjectAndEntries) {
    const scene::Texture p = texture_of(
        "sphere { 0, 1 pigment { object { box { -1, 1 } rgb 1, rgb <1, 0, 0> } scale 2 } }");
    const auto* k = std::get_if<pattern::Object>(&p.pigment->pattern.kind);
    ASSERT_NE(k, nullptr);
    ASSERT_TRUE(k->object);
    EXPECT_TRUE(std::holds_alternative<scene::Box>(k->object->shape));
    ASSERT_EQ(p.pigment->colour_map.size(), 2u);
    EXPECT_DOUBLE_EQ(p.pigment->colour_map[1].item.g, 0);
    EXPECT_FALSE(p.pigment->pattern.unsupported.has_value());

    const scene::Texture t = texture_of(
        "sphere { 0, 1 texture { object { sphere { 0, 1 } texture { pigment { rgb 1 } }, "
        "texture { pigment { rgb 0 } } } } }");
    EXPECT_EQ(t.texture_map.size(), 2u);
    const scene::Texture n = texture_of(
        "sphere { 0, 1 normal { object { sphere { 0, 1 } normal { bumps }, normal { dents } } } }");
    EXPECT_EQ(n.normal->normal_map.size(), 2u);

    const scene::Scene s = run("sphere { 0, 1 pigment { object { lemon { } } } }");
    ASSERT_EQ(s.unsupported.size(), 1u);
    EXPECT_EQ(s.unsupported[0].feature, "lemon");

    EXPECT_NE(error_of("sphere { 0, 1 pigment { object { 1 } } }").find("expected an object"),
              std::string::npos);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { object { sphere { 0, 1 } rgb 1, rgb 0, rgb 1 } } }")
                  .find("unexpected"),
              std::string::npos);
}

// POV stores these in single precision; lumen rounds them the same way when it reads them.
TEST_F(BuildPattern, SinglePrecisionParameters) {
    const scene::Texture t = texture_of(
        "sphere { 0, 1 pigment { agate agate_turb 0.3 frequency 0.7 phase 0.1 poly_wave 1.3 "
        "turbulence 0.5 omega 0.6 lambda 2.2 warp { turbulence 0.1 omega 0.35 lambda 1.9 } } }");
    const scene::Pattern& p = t.pigment->pattern;
    EXPECT_EQ(p.frequency, double(0.7f));
    EXPECT_EQ(p.phase, double(0.1f));
    EXPECT_EQ(p.wave_exponent, double(1.3f));
    EXPECT_EQ(std::get<pattern::Agate>(p.kind).agate_turb, double(0.3f));
    EXPECT_EQ(p.steps.classic_turbulence()->omega, double(0.6f));
    EXPECT_EQ(p.steps.classic_turbulence()->lambda, double(2.2f));
    const auto& warp = std::get<scene::warp::Turbulence>(p.steps.steps.back());
    EXPECT_EQ(warp.omega, double(0.35f));
    EXPECT_EQ(warp.lambda, double(1.9f));
    expect_vec(p.steps.classic_turbulence()->amount, {0.5, 0.5, 0.5});  // double
}

TEST_F(BuildPattern, SpiralArmsAreTruncatedAndMarbleWoodSpiralsDefaultToTriangleWaves) {
    const scene::Pattern s1 = texture_of("sphere { 0, 1 pigment { spiral1 3.7 } }").pigment->pattern;
    EXPECT_EQ(std::get<pattern::Spiral1>(s1.kind).arms, 3);
    EXPECT_EQ(s1.wave, scene::WaveType::Triangle);
    EXPECT_EQ(std::get<pattern::Spiral2>(
                  texture_of("sphere { 0, 1 pigment { spiral2 -2.5 } }").pigment->pattern.kind)
                  .arms,
              -2);
    EXPECT_NE(error_of("sphere { 0, 1 pigment { spiral1 } }"), "no error");
    for (const char* kw : {"marble", "wood"})
        EXPECT_EQ(texture_of(std::string("sphere { 0, 1 pigment { ") + kw + " } }").pigment->pattern.wave,
                  scene::WaveType::Triangle)
            << kw;
    EXPECT_EQ(texture_of("sphere { 0, 1 pigment { marble ramp_wave } }").pigment->pattern.wave,
              scene::WaveType::Ramp);
    EXPECT_EQ(texture_of("sphere { 0, 1 pigment { bozo } }").pigment->pattern.wave,
              scene::WaveType::Ramp);
}

// The scene's noise generator and number of waves reach every pattern through one shared
// record, filled in once the whole scene is read: a global_settings after the pattern counts,
// and without one the generator follows the final #version (1 below 3.5).
TEST_F(BuildPattern, PatternsSeeTheFinalGlobalSettings) {
    const scene::Scene late = run(
        "sphere { 0, 1 pigment { bozo } }\n"
        "global_settings { noise_generator 3 number_of_waves 4 }");
    const scene::Pattern& p = late.objects[0]->texture.back()->pigment->pattern;
    ASSERT_TRUE(p.globals);
    EXPECT_EQ(p.globals->noise_generator, 3);
    EXPECT_EQ(p.globals->number_of_waves, 4);
    auto generator = [&](const std::string& text) {
        const scene::Scene s = run(text);
        EXPECT_EQ(s.objects[0]->texture.back()->pigment->pattern.globals->noise_generator,
                  s.globals.noise_generator);
        return s.globals.noise_generator;
    };
    EXPECT_EQ(generator("sphere { 0, 1 pigment { bozo } }"), 2);
    EXPECT_EQ(generator("#version 3.1;\nsphere { 0, 1 pigment { bozo } }"), 1);
    EXPECT_EQ(generator("#version 3.1;\nsphere { 0, 1 pigment { bozo } }\n#version 3.7;"), 2);
    EXPECT_EQ(generator("#version 3.1;\nglobal_settings { noise_generator 2 }\n"
                        "sphere { 0, 1 pigment { bozo } }"),
              2);
    const scene::Scene many = run("global_settings { number_of_waves 20000 }");
    ASSERT_EQ(many.unsupported.size(), 1u);
    EXPECT_EQ(many.unsupported[0].feature, "number_of_waves above 10000");
}

}  // namespace
}  // namespace lumen::interp::testing

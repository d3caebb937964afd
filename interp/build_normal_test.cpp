// normal { }: which patterns render as normals, the amount and accuracy in single precision,
// slope_map and normal_map (one map per normal, the last written wins), the reports of
// unrendered patterns anywhere in a normal, and transforms that leave a normal_map's entries
// in the parent's pattern space.
#include "interp/build_test_support.hpp"
#include "scene/normal_forms.hpp"

namespace lumen::interp::testing {
namespace {

using BuildNormal = BuildTest;

std::string normal_text(std::string_view keyword) {
    std::string body = pattern_with_arguments(keyword);
    if (keyword == "average") body += " normal_map { [1 gradient x] }";
    if (keyword == "pigment_pattern") body += " { rgb 1 }";
    return "sphere { 0, 1 normal { " + body + " } }";
}

// Every table kind reads in a normal; it is reported unsupported exactly when lumen does not
// render it as a normal, under "normal 'kind'".
TEST_F(BuildNormal, EveryKindIsReportedUnlessItRendersAsANormal) {
    int rendered = 0;
    for (const scene::PatternInfo& row : scene::kPatternTable) {
        if (row.keyword.empty() || row.keyword == "function" || row.keyword == "object") continue;
        const scene::Texture t = texture_of(normal_text(row.keyword));
        const scene::Pattern& p = t.normal->pattern;
        EXPECT_EQ(p.type(), row.type) << row.keyword;
        const bool expected = scene::normal_rendered(row.type);
        EXPECT_EQ(p.unsupported.has_value(), !expected) << row.keyword;
        if (p.unsupported) {
            EXPECT_EQ(p.unsupported->feature, "normal '" + std::string(row.keyword) + "'");
        }
        rendered += expected;
    }
    // The differenced kinds that render for pigments, bumps, wrinkles, quilted, facets and
    // average.
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Bumps));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Wrinkles));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Quilted));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Average));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Gradient));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Facets));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Dents));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Pavement));
    EXPECT_TRUE(scene::normal_rendered(scene::PatternType::Function));  // differenced
    EXPECT_GE(rendered, 30);
}

TEST_F(BuildNormal, AmountAndAccuracyAreSinglePrecision) {
    const scene::Texture a = texture_of("sphere { 0, 1 normal { gradient x 0.3 accuracy 0.07 } }");
    EXPECT_EQ(a.normal->amount, double(0.3f));
    EXPECT_EQ(a.normal->accuracy, double(0.07f));
    const scene::Texture b = texture_of("sphere { 0, 1 normal { gradient x 2 bump_size 0.3 } }");
    EXPECT_EQ(b.normal->amount, double(0.3f));  // the last one written
    const scene::Texture c = texture_of("sphere { 0, 1 normal { gradient x } }");
    EXPECT_EQ(c.normal->amount, 0.5);
}

TEST_F(BuildNormal, SlopeMapEntries) {
    const scene::Texture t = texture_of(
        "#declare S = slope_map { [0.3 <1, -1>] }\n"
        "sphere { 0, 1 normal { onion slope_map { [0 <0, 1>] [0.1 0.5] S } } }");
    const scene::SlopeMap& m = t.normal->slope_map;
    ASSERT_EQ(m.size(), 3u);
    EXPECT_EQ(m[0].item, glm::dvec2(0, 1));
    EXPECT_EQ(m[1].value, double(0.1f));      // keys in single precision, like every map's
    EXPECT_EQ(m[1].item, glm::dvec2(0.5, 0.5));  // a float is <f, f>
    EXPECT_EQ(m[2].item, glm::dvec2(1, -1));
    EXPECT_TRUE(warnings.empty());
    EXPECT_NE(error_of("sphere { 0, 1 normal { onion slope_map { [0 <0, 1, 2>] } } }"), "no error");
    EXPECT_NE(error_of("sphere { 0, 1 normal { onion slope_map { [0 <0, 1> 3] } } }"), "no error");
}

// POV keeps one map per normal: a slope_map and a normal_map (or list entries) replace each
// other, so povray renders `slope_map {...} normal_map {...}` as the normal_map alone.
TEST_F(BuildNormal, SlopeMapAndNormalMapReplaceEachOther) {
    const scene::Texture map_last = texture_of(
        "sphere { 0, 1 normal { gradient x slope_map { [0 <0, 1>] } "
        "normal_map { [0 gradient y] [1 onion] } } }");
    EXPECT_TRUE(map_last.normal->slope_map.empty());
    EXPECT_EQ(map_last.normal->normal_map.size(), 2u);
    const scene::Texture slopes_last = texture_of(
        "sphere { 0, 1 normal { gradient x normal_map { [0 gradient y] [1 onion] } "
        "slope_map { [0 <0, 1>] } } }");
    EXPECT_TRUE(slopes_last.normal->normal_map.empty());
    EXPECT_EQ(slopes_last.normal->slope_map.size(), 1u);
}

// An unrendered pattern inside a normal_map entry is reported like one at the top.
TEST_F(BuildNormal, UnrenderedEntriesAreReported) {
    const scene::Scene s = run(
        "sphere { 0, 1 normal { gradient x normal_map { [0 gradient y] "
        "[1 pigment_pattern { facets }] } } }");
    ASSERT_EQ(s.unsupported.size(), 1u);
    EXPECT_EQ(s.unsupported[0].feature, "pattern 'facets'");
    EXPECT_TRUE(run("sphere { 0, 1 normal { checker normal { quilted } normal { onion } } }")
                    .unsupported.empty());
}

// The object's transforms move the normal; its entries are evaluated in its pattern space, so
// they are not given a copy (povray: a parent `scale 2` scales its entries once).
TEST_F(BuildNormal, TransformsStayWithTheParent) {
    const scene::Texture t = texture_of(
        "sphere { 0, 1 normal { gradient x normal_map { [0 gradient y scale 0.3] [1 onion] } "
        "scale 2 } translate x }");
    EXPECT_EQ(t.normal->pattern.steps.steps.size(), 1u);  // scale 2, then translate x
    const scene::Normal& entry = *t.normal->normal_map[0].item;
    ASSERT_EQ(entry.pattern.steps.steps.size(), 1u);
    expect_vec(std::get<scene::Transform>(entry.pattern.steps.steps[0]).point({1, 1, 1}),
               {0.3, 0.3, 0.3});
    EXPECT_TRUE(t.normal->normal_map[1].item->pattern.steps.steps.empty());
}

}  // namespace
}  // namespace lumen::interp::testing

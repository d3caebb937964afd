// ItemCursor and the builders driven by hand-made items (no parser involved).
#include "interp/build_common.hpp"
#include "interp/build_test_support.hpp"
#include "parser/keywords.hpp"

namespace lumen::interp::testing {
namespace {

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const LumenError& e) {
        return e.diag.loc.str() + ": " + e.diag.message;
    }
    return "no error";
}

TEST(ItemCursor, SkipsCommasAndReadsTypedValues) {
    BuildContext ctx;
    std::vector<Item> items = {vec3(1, 2, 3), comma(), val(2.5), comma(), val(std::string("s"))};
    ItemCursor cur(ctx, items, "sphere", {});
    expect_vec(cur.expect_vector(""), {1, 2, 3});
    EXPECT_DOUBLE_EQ(cur.expect_float(""), 2.5);
    EXPECT_EQ(cur.expect_string(""), "s");
    EXPECT_TRUE(cur.at_end());
}

TEST(ItemCursor, PromotesFloatToVectorAndColour) {
    BuildContext ctx;
    std::vector<Item> items = {val(2.0), val(0.5), vec3(1, 0, 0), kw("filter"), val(0.25)};
    ItemCursor cur(ctx, items, "test", {});
    expect_vec(cur.expect_vector(""), {2, 2, 2});
    scene::Colour all = cur.expect_colour("");
    EXPECT_EQ(all, (scene::Colour{0.5, 0.5, 0.5, 0.5, 0.5}));
    scene::Colour red = cur.expect_colour("");
    EXPECT_EQ(red, (scene::Colour{1, 0, 0, 0.25, 0}));
}

TEST(ItemCursor, ErrorNamesKeywordAndFoundType) {
    BuildContext ctx;
    std::vector<Item> items = {kw("translate", 3), val(std::string("x"), 13)};
    ItemCursor cur(ctx, items, "sphere", {});
    cur.next();
    EXPECT_EQ(message_of([&] { cur.expect_vector("translate"); }),
              "<command line>: expected a vector after 'translate', found a string");
}

TEST(ItemCursor, UnknownKeywordSuggestsClosest) {
    BuildContext ctx;
    std::vector<Item> items = {kw("phong_sise", 5)};
    ItemCursor cur(ctx, items, "finish", {});
    try {
        cur.fail_unexpected(cur.next(), {"phong", "phong_size", "specular"});
        FAIL();
    } catch (const LumenError& e) {
        EXPECT_EQ(e.diag.message, "'phong_sise' is not a finish keyword");
        EXPECT_EQ(e.diag.hint, "did you mean 'phong_size'?");
        EXPECT_EQ(e.diag.loc.column, 5u);
    }
}

TEST(ItemCursor, OptionalBool) {
    BuildContext ctx;
    std::vector<Item> items = {val(0.0), kw("x")};
    ItemCursor cur(ctx, items, "t", {});
    EXPECT_FALSE(cur.optional_bool());
    EXPECT_TRUE(cur.optional_bool());  // no float follows: the flag alone means on
}

TEST(BuildBlock, SphereFromHandMadeItems) {
    BuildContext ctx;
    BlockValue b{"sphere", {vec3(1, 2, 3), comma(), val(4.0), kw("translate"), vec3(0, 1, 0)}, {}};
    Value v = build_block(ctx, b);
    ASSERT_TRUE(v.is<scene::ObjectPtr>());
    const scene::Object& o = *v.as<scene::ObjectPtr>();
    const auto& s = std::get<scene::Sphere>(o.shape);
    expect_vec(s.center, {1, 2, 3});
    EXPECT_DOUBLE_EQ(s.radius, 4.0);
    expect_vec(o.transform.point({0, 0, 0}), {0, 1, 0});
}

TEST(BuildBlock, DataBlocksComeBackAsBlockValues) {
    BuildContext ctx;
    BlockValue b{"vertex_vectors", {val(1.0), vec3(0, 0, 0)}, {}};
    Value v = build_block(ctx, b);
    ASSERT_TRUE(v.is<std::shared_ptr<const BlockValue>>());
    EXPECT_EQ(v.as<std::shared_ptr<const BlockValue>>()->keyword, "vertex_vectors");
    EXPECT_TRUE(is_supported_block("reflection"));
    EXPECT_FALSE(is_supported_block("lemon"));
    const auto& known = known_block_keywords();
    EXPECT_NE(std::find(known.begin(), known.end(), "isosurface"), known.end());
}

// The shape list's keywords are POV-Ray reserved words; the listed shapes build objects and
// the unrendered ones do not.
TEST(BuildBlock, ShapeListKeywordsAreReservedBlocks) {
    for (std::string_view kw : scene::kShapeKeywords) {
        EXPECT_TRUE(parser::is_reserved(kw)) << kw;
        EXPECT_TRUE(is_supported_block(std::string(kw))) << kw;
    }
    for (std::string_view kw : scene::kUnsupportedShapeKeywords) {
        EXPECT_TRUE(parser::is_reserved(kw)) << kw;
        EXPECT_FALSE(is_supported_block(std::string(kw))) << kw;
        EXPECT_TRUE(is_unsupported_shape(std::string(kw))) << kw;
    }
}

TEST(BuildBlock, DefaultPigmentStartsNewTextures) {
    BuildContext ctx;
    BlockValue pig{"pigment", {val(scene::Colour{1, 0, 0, 0, 0})}, {}};
    BlockValue def{"default", {val(build_block(ctx, pig).as<scene::PigmentPtr>())}, {}};
    apply_default(ctx, def);
    BlockValue tex{"texture", {}, {}};
    Value t = build_block(ctx, tex);
    const auto& layers = t.as<std::shared_ptr<const TextureValue>>()->layers;
    ASSERT_EQ(layers.size(), 1u);
    ASSERT_TRUE(layers[0]->pigment);
    EXPECT_EQ(layers[0]->pigment->colour, (scene::Colour{1, 0, 0, 0, 0}));
}

TEST(BuildBlock, TopLevelKeywordIsAnError) {
    BuildContext ctx;
    scene::Scene s;
    EXPECT_EQ(message_of([&] { apply_top_level(ctx, s, kw("translate")); }),
              "<command line>: unexpected 'translate' at top level");
}

}  // namespace
}  // namespace lumen::interp::testing

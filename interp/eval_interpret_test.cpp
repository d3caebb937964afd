// interpret_text end to end: evaluated values reach the scene through the builders.
#include <gtest/gtest.h>

#include "interp/dump_scene.hpp"
#include "interp/interpret.hpp"

namespace lumen::interp {
namespace {

scene::Scene interpret(const std::string& text, const InterpOptions& options = {}) {
    static SourceManager sources;  // diagnostics in a failing test may point into it
    return interpret_text(sources, "scene.pov", text, options);
}

std::string first_error_line(const std::string& text) {
    try {
        interpret(text);
    } catch (const LumenError& e) {
        return format_headline(e.diag);
    }
    return "";
}

const scene::Sphere& sphere_at(const scene::Scene& s, size_t i) {
    return std::get<scene::Sphere>(s.objects.at(i)->shape);
}

TEST(InterpretTest, ComputedValuesReachTheScene) {
    auto s = interpret("#declare R = 0.5;\n#declare P = <1, 2, 3> * 2;\nsphere { P, R * 2 }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(sphere_at(s, 0).center, glm::dvec3(2, 4, 6));
    EXPECT_DOUBLE_EQ(sphere_at(s, 0).radius, 1.0);
}

TEST(InterpretTest, ASceneLeftForTheExitIsTheSameScene) {
    // With leave_for_exit the evaluator and the tree outlive the call (the process frees them
    // as it exits); what reaches the scene from them (declared textures, compiled functions,
    // macro output, literal runs of a mesh) must not depend on it.
    const std::string text =
        "#declare T = texture { pigment { granite scale 0.2 } finish { phong 0.5 } }\n"
        "#declare F = function(x, y, z) { x * x + y * y + z * z - 1 }\n"
        "#macro Ball(P) sphere { P, 0.5 texture { T } } #end\n"
        "#for (I, 0, 3) Ball(<I, 0, 0>) #end\n"
        "isosurface { function { F(x, y, z) } contained_by { box { -2, 2 } } }\n"
        "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }\n";
    InterpOptions left;
    left.leave_for_exit = true;
    const std::string kept = dump_scene_json(interpret(text));
    EXPECT_EQ(dump_scene_json(interpret(text, left)), kept);
    EXPECT_NE(kept.find("isosurface"), std::string::npos);
}

TEST(InterpretTest, LoopsMakeObjects) {
    auto s = interpret("#for (I, 1, 3) sphere { <I, 0, 0>, I / 10 } #end\n");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(sphere_at(s, 2).center.x, 3);
    EXPECT_DOUBLE_EQ(sphere_at(s, 1).radius, 0.2);
}

TEST(InterpretTest, MacroProducesItemsInsideABlock) {
    auto s = interpret("#macro Centre() <0, 1, 0>, #end\n#macro Size(K) K * 0.25 #end\n"
                       "sphere { Centre() Size(2) }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(sphere_at(s, 0).center, glm::dvec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(sphere_at(s, 0).radius, 0.5);
}

TEST(InterpretTest, DeclaredObjectsAndUnions) {
    auto s = interpret("#declare Ball = sphere { 0, 1 }\n"
                       "union { object { Ball } object { Ball translate x } }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& csg = std::get<scene::Csg>(s.objects[0]->shape);
    EXPECT_EQ(csg.children.size(), 2u);
}

TEST(InterpretTest, VersionReachesTheScene) {
    auto legacy = interpret("sphere { 0, 1 }\n");
    EXPECT_FALSE(legacy.version_given);
    EXPECT_DOUBLE_EQ(legacy.language_version, 3.62);
    auto modern = interpret("#version 3.7;\nsphere { 0, 1 }\n");
    EXPECT_TRUE(modern.version_given);
    EXPECT_DOUBLE_EQ(modern.language_version, 3.7);
    InterpOptions o;
    o.version = 3.7;
    EXPECT_TRUE(interpret("sphere { 0, 1 }\n", o).version_given);
}

// What every standard include does around its body: in a scene without #version it leaves
// version 3.7 in effect, as POV-Ray does (measured: colors.inc brightens such a scene to sRGB).
TEST(InterpretTest, IncludeRestoringTheVersionGivesA37Scene) {
    auto s = interpret("#declare T = version;\n#version 3.5;\n#version T;\nsphere { 0, 1 }\n");
    EXPECT_TRUE(s.version_given);
    EXPECT_DOUBLE_EQ(s.language_version, 3.7);
}

TEST(InterpretTest, CommandLineDeclares) {
    InterpOptions o;
    o.declares = {{"Foo", 0.123456789, ""}, {"Name", std::nullopt, "abc"}};
    auto s = interpret("#if (strcmp(Name, \"abc\") = 0) sphere { 0, Foo } #end\n", o);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_DOUBLE_EQ(sphere_at(s, 0).radius, 0.123457);  // 6 significant digits, as POV
}

TEST(InterpretTest, UnknownBlockKeywordSuggestsTheRightOne) {
    try {
        interpret("\nspere { 0, 1 }\n");
        FAIL() << "expected an error";
    } catch (const LumenError& e) {
        EXPECT_EQ(e.diag.message, "unknown keyword 'spere'");
        EXPECT_EQ(e.diag.hint, "did you mean 'sphere'?");
        EXPECT_EQ(e.diag.loc.line, 2u);
        EXPECT_EQ(e.diag.loc.column, 1u);
    }
}

TEST(InterpretTest, ReservedButUnsupportedBlocksAreNotEvaluated) {
    // The lemon's body refers to names that do not exist: it must not be evaluated.
    auto s = interpret("#declare P = lemon { Undefined_Fn(x, y, z) Whatever }\n"
                       "sphere { 0, 1 }\n");
    EXPECT_EQ(s.objects.size(), 1u);
}

TEST(InterpretTest, BareModifierAtTopLevelIsAnError) {
    EXPECT_EQ(first_error_line("sphere { 0, 1 }\ntranslate x\n"),
              "scene.pov:2:1: error: unexpected 'translate' at top level");
}

TEST(InterpretTest, ErrorsCarryTheirLocation) {
    EXPECT_EQ(first_error_line("#declare A = 1;\nsphere { <A, B, 0>, 1 }\n"),
              "scene.pov:2:14: error: undeclared identifier 'B'");
}

}  // namespace
}  // namespace lumen::interp

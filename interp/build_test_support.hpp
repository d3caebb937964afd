// Shared helpers for the builders' unit tests (interp/build_*_test.cpp): run SDL text through
// the whole interpreter, or build blocks from hand-made items.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "interp/builders.hpp"
#include "interp/dump_scene.hpp"
#include "interp/interpret.hpp"

namespace lumen::interp::testing {

class BuildTest : public ::testing::Test {
protected:
    SourceManager sources;
    InterpOptions options;
    std::vector<Diagnostic> warnings;

    scene::Scene run(const std::string& text) {
        return interpret_text(sources, "t.pov", text, options,
                              [this](const Diagnostic& d) { warnings.push_back(d); });
    }
    // The first line of the error `text` raises, or "no error".
    std::string error_of(const std::string& text) {
        try {
            run(text);
        } catch (const LumenError& e) {
            return format_headline(e.diag);
        }
        return "no error";
    }
    scene::ObjectPtr first_object(const std::string& text) {
        scene::Scene s = run(text);
        if (s.objects.empty()) throw std::runtime_error("no object");
        return s.objects.front();
    }
    template <class Shape> Shape shape_of(const std::string& text) {
        return std::get<Shape>(first_object(text)->shape);
    }
    // The top texture layer of the first object.
    scene::Texture texture_of(const std::string& text) {
        scene::ObjectPtr o = first_object(text);
        if (o->texture.empty()) throw std::runtime_error("no texture");
        return *o->texture.back();
    }
};

// Hand-made items, for testing builders without the parser.
inline Item kw(const std::string& word, uint32_t col = 1) {
    Item it;
    it.kind = Item::Kind::Keyword;
    it.keyword = word;
    it.loc.line = 1;
    it.loc.column = col;
    return it;
}
template <class T> Item val(T v, uint32_t col = 1) {
    Item it;
    it.kind = Item::Kind::Value;
    it.value.v = std::move(v);
    it.loc.line = 1;
    it.loc.column = col;
    return it;
}
inline Item vec3(double x, double y, double z, uint32_t col = 1) {
    return val(VecN{{x, y, z}}, col);
}
inline Item comma() {
    Item it;
    it.kind = Item::Kind::Comma;
    return it;
}

inline void expect_vec(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-9) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// A pattern keyword with the arguments it needs (a pigment_map or normal_map for average is
// the caller's).
inline std::string pattern_with_arguments(std::string_view keyword) {
    std::string body(keyword);
    if (keyword == "gradient" || keyword == "slope") body += " y";
    if (keyword == "spiral1" || keyword == "spiral2") body += " 2";
    if (keyword == "mandel" || keyword == "tiling") body += " 10";
    if (keyword == "julia") body += " <0.3, 0.2>, 10";
    if (keyword == "magnet") body += " 1 mandel 10";
    if (keyword == "density_file")
        body += std::string(" df3 \"") + LUMEN_SOURCE_DIR + "/tests/patterns/grid16.df3\"";
    return body;
}

}  // namespace lumen::interp::testing

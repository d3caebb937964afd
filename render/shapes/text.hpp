// text: TrueType glyph outlines extruded along +z from z = 0 to the thickness, one solid per
// character (POV-Ray builds a union of glyphs: a point is inside when it is inside any).
#pragma once
#include <vector>

#include "render/bvh.hpp"
#include "render/shapes/shape.hpp"

namespace lumen::render {

// One side wall of a glyph: the straight edge a -> b, or the quadratic Bezier a, c, b.
struct GlyphEdge {
    glm::dvec2 a{0}, c{0}, b{0};
    bool curve = false;
    double outward = 1;  // +1: (dy, -dx) points out of the glyph, -1: it points in
    glm::dvec2 lo{0}, hi{0};  // box of a, c and b, which holds the edge: rays passing it skip it
};

struct PreparedGlyph {
    glm::dvec3 position{0};  // the glyph's origin in the text's space
    std::vector<GlyphEdge> edges;
    glm::dvec2 lo{0}, hi{0};  // box of every outline point, in the glyph's space
};

struct TextShape {
    std::vector<PreparedGlyph> glyphs;  // only glyphs with an outline, in the tree's order
    double thickness = 1;
    Aabb box;
    Bvh tree;  // over the glyphs' boxes: a ray tests the few glyphs it passes
};

TextShape make_text(const scene::Text& t);
bool intersect(const TextShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const TextShape& s, const glm::dvec3& p);
Aabb bounds(const TextShape& s);
inline Aabb solid_bounds(const TextShape& s) { return bounds(s); }

// The even-odd test of one glyph at a point of its plane (POV-Ray's crossing rules).
bool inside_glyph(const PreparedGlyph& g, const glm::dvec2& q);

template <> struct ShapeTraits<scene::Text> : PreparedBy<scene::Text, TextShape, make_text> {
    // Not baked: the outlines are traced in the text's space under its transform.
    static bool bake(const scene::Text&, const scene::Transform&, TextShape&) { return false; }
};

}  // namespace lumen::render

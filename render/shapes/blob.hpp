// blob: the surface where the summed density of the components equals the threshold, found
// as POV-Ray finds it. Each component is one element (a sphere) or three (a cylinder: the
// open cylinder and the hemispheres at its ends); along a ray, each element's density is a
// quartic between the points where the ray enters and leaves it. The running sum of those
// quartics is solved between consecutive entry/exit points with POV-Ray's solver
// (render/pov_polynomial.hpp), after a Bernstein bound has ruled out the pieces with no root.
#pragma once
#include <cstdint>
#include <vector>

#include "render/bvh.hpp"
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct BlobElement {
    enum class Kind : uint8_t { Sphere, Cylinder, BaseCap, ApexCap };
    Kind kind = Kind::Sphere;
    int component = 0;
    int transform = -1;        // index into BlobShape::to_component, -1: none
    glm::dvec3 centre{0};      // sphere centre, or the cylinder's base
    glm::dvec3 axis{0, 0, 1};  // unit axis (cylinders and caps)
    double length = 0;         // axis length
    double rad2 = 1;           // radius squared
    double c[3] = {1, -2, 1};  // density c[0] d^4 + c[1] d^2 + c[2] for d^2 < rad2
};

struct BlobShape {
    double threshold = 1;
    bool sturm = false;
    bool valid = false;
    std::vector<BlobElement> elements;
    std::vector<scene::Transform> to_component;  // the components' transforms (m: to blob space)
    // Over the elements' boxes (the hierarchy POV-Ray builds for its own speed), a long
    // cylinder's split into pieces along its axis so that its box does not cover the blob:
    // box_element maps the tree's boxes to elements, and `pieces` says whether any is split.
    Bvh tree;
    std::vector<uint32_t> box_element;
    bool pieces = false;
    Aabb box;    // every element's box: the span the solver's sweep is scaled to
    // Where the blob can be: the boxes of its elements of positive strength alone, as
    // POV-Ray bounds a blob (elsewhere the density is at most 0, below any threshold above
    // the inside test's tolerance); `box` for a lower threshold.
    Aabb bound;
    // The components' own textures (null: the blob's), when any component has one.
    std::vector<const scene::LayeredTexture*> textures;
    bool textured = false;
};

BlobShape make_blob(const scene::Blob& b);
bool intersect(const BlobShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const BlobShape& s, const glm::dvec3& p);
inline Aabb bounds(const BlobShape& s) { return s.bound; }
inline Aabb solid_bounds(const BlobShape& s) { return s.bound; }

// The summed density at p minus nothing (compare with s.threshold), and its gradient.
double blob_density(const BlobShape& s, const glm::dvec3& p);
glm::dvec3 blob_gradient(const BlobShape& s, const glm::dvec3& p);
// Calls f(component, |density|) for each element with a non-zero density at p.
template <class F> void for_each_blob_density(const BlobShape& s, const glm::dvec3& p, F&& f);
double blob_element_density(const BlobShape& s, const BlobElement& e, const glm::dvec3& p);

template <class F> void for_each_blob_density(const BlobShape& s, const glm::dvec3& p, F&& f) {
    for (const BlobElement& e : s.elements) {
        const double d = blob_element_density(s, e, p);
        if (d != 0) f(e.component, d < 0 ? -d : d);
    }
}

inline constexpr double kDepthBlob = 1e-2;  // POV-Ray's DEPTH_TOLERANCE for blobs

template <>
struct ShapeTraits<scene::Blob> : PreparedBy<scene::Blob, BlobShape, make_blob, &kDepthBlob> {
    // Not baked: the solver works along the normalised ray in the blob's own space.
    static bool bake(const scene::Blob&, const scene::Transform&, BlobShape&) { return false; }
};

}  // namespace lumen::render

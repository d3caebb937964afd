// isosurface: the surface where a compiled function equals the threshold, inside a box or
// sphere container, found as POV-Ray 3.7 finds it: the ray cut at the container, each piece
// bisected while the Lipschitz bound (max_gradient) allows a root, the depth being the far end
// of the first interval narrower than the accuracy whose end value is below the threshold.
// Normals are forward differences with the accuracy as step.
#pragma once
#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "function/vm.hpp"
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct IsosurfaceShape {
    scene::Isosurface iso;
    fn::Context context;
    bool valid = false;
    uint64_t id = 0;  // unique per prepared shape, kept by its copies: the cross-ray cache's key
    // The steepest slope the searches met (per object-space unit), for the warning after the
    // render; shared by the copies of the shape and raised by every thread.
    std::shared_ptr<std::atomic<double>> gradient_found = std::make_shared<std::atomic<double>>(0);
};

// POV-Ray's warning after a render where max_gradient was too low (the surface may have holes)
// or far too high (slow), from the slope the searches met; none with `evaluate`, or when the
// slope found is as set.
std::optional<std::string> gradient_warning(const IsosurfaceShape& s);

IsosurfaceShape make_isosurface(const scene::Isosurface& s);
bool intersect(const IsosurfaceShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const IsosurfaceShape& s, const glm::dvec3& p);
Aabb bounds(const IsosurfaceShape& s);
inline Aabb solid_bounds(const IsosurfaceShape& s) { return bounds(s); }

// Every hit POV-Ray records along o + t d (d the object-space image of a unit world
// direction), sorted by depth, up to max_trace + 1; returns the count.
struct IsoHit {
    double t;
    glm::dvec3 normal;  // object space, unit
};
constexpr int kMaxIsoHits = 12;
int isosurface_hits(const IsosurfaceShape& s, const LocalRay& r, IsoHit* hits);

// While one lives, this thread's rays are shadow rays (Query::Shadow): their failed root
// searches are not remembered by the cross-ray cache (POV-Ray's rule).
class ShadowRayMark {
public:
    explicit ShadowRayMark(bool shadow);
    ~ShadowRayMark();
    ShadowRayMark(const ShadowRayMark&) = delete;
    ShadowRayMark& operator=(const ShadowRayMark&) = delete;

private:
    bool previous_;
};

inline constexpr double kDepthIsosurface = 1e-4;

template <>
struct ShapeTraits<scene::Isosurface>
    : PreparedBy<scene::Isosurface, IsosurfaceShape, make_isosurface, &kDepthIsosurface> {
    // Traced in its own space, where the function is written.
    static bool bake(const scene::Isosurface&, const scene::Transform&, IsosurfaceShape&) {
        return false;
    }
};

}  // namespace lumen::render

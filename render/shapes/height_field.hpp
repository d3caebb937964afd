// height_field: two triangles per grid cell, searched along the ray by a walk over a pyramid
// of blocks (8 x 8 cells, 64 x 64, ...) and the cells in them, each skipped when the ray's
// height range misses theirs (the same hits as POV-Ray's two-level walk, found faster). The object transform is held by the shape (always baked): smooth normals are
// blended after each corner normal has gone to world space, as POV-Ray blends them.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "render/shapes/shape.hpp"

namespace lumen::render {

struct HeightFieldShape {
    std::shared_ptr<const std::vector<uint16_t>> heights;  // the scene's grid, Map[z][x]
    int columns = 0, rows = 0;
    // Grid units (x, z: one cell; y: one height level) to the space rays arrive in.
    scene::Transform grid_to_space;
    double floor = 0, top = 0;  // the searched box's y range, in height levels
    double water = 0;           // the water level in height levels (inside below it)
    // Level 0: the cells; level k: blocks of 8^k x 8^k cells; the last has few blocks.
    struct Level {
        int size = 1, columns = 0, rows = 0;               // cells per side; block counts
        std::vector<std::array<uint16_t, 2>> range;        // min and max height in each block
    };
    std::vector<Level> levels;
    bool smooth = false;
    std::vector<std::array<int16_t, 3>> normals;  // per vertex, int(32767 n), smooth only
    bool valid = false;

    double at(int x, int z) const { return (*heights)[size_t(z) * size_t(columns) + size_t(x)]; }
};

// `to_space` is the object's transform, or identity when rays arrive in object space.
std::unique_ptr<HeightFieldShape> make_height_field(const scene::HeightField& hf,
                                                    const scene::Transform& to_space);
bool intersect(const HeightFieldShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const HeightFieldShape& s, const glm::dvec3& p);
Aabb bounds(const HeightFieldShape& s);        // the searched box
Aabb solid_bounds(const HeightFieldShape& s);  // the box and the column below it

using HeightFieldPtr = std::unique_ptr<HeightFieldShape>;  // shape.hpp forwards to it

template <> struct ShapeTraits<scene::HeightField> {
    using Prepared = HeightFieldPtr;
    static constexpr double min_depth = kDepthDefault;
    static Prepared prepare(const scene::HeightField& hf, bool) {
        return make_height_field(hf, scene::Transform{});
    }
    static bool bake(const scene::HeightField& hf, const scene::Transform& xf, Prepared& out) {
        out = make_height_field(hf, xf);
        return out->valid;
    }
};

}  // namespace lumen::render

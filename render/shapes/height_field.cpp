// height_field as POV-Ray 3.7 intersects it. In grid units (cells of 1, heights 0..65535):
// the ray is clipped to the box x in [0, W-1], z in [0, H-1], y from the water level (or the
// lowest height) - 0.001 to the highest + 0.001, and only hits inside that box count, so
// nothing below the water is drawn. Cell (x, z) holds the triangles (x, z)(x+1, z)(x, z+1)
// and (x+1, z+1)(x, z+1)(x+1, z), each with POV-Ray's acceptance tolerances (1e-4 outside
// the triangle). The cells are walked in ray order and the first cell with a hit answers
// with its nearer triangle; a CSG parent asks again from beyond that hit for the next one.
#include "render/shapes/height_field.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace lumen::render {

namespace {

constexpr double kEps = 1e-10;
constexpr double kSideTolerance = 1e-4;  // how far outside its triangle a hit still counts

// The ray in grid units, with the reciprocals of its x and z directions (0 where the ray
// does not move along the axis) for the walk.
struct GridRay {
    glm::dvec3 o, d;
    double inv_x = d.x != 0 ? 1 / d.x : 0, inv_z = d.z != 0 ? 1 / d.z : 0;
    double y(double t) const { return o.y + t * d.y; }
};

// Walks the square cells of side `size` (indices x_lo..x_hi, z_lo..z_hi) that the ray's x-z
// projection crosses between t0 and t1, in ray order: visit(ix, iz, ta, tb) returns true to
// stop the walk (the walk then returns true). Bounded by the number of cells on the way.
template <class Visit>
bool walk(const GridRay& r, double size, int x_lo, int x_hi, int z_lo, int z_hi, double t0,
          double t1, Visit&& visit) {
    constexpr double inf = Aabb::inf;
    const double per_cell = 1 / size;  // exact: sizes are powers of 2
    auto cell = [&](double p, int lo, int hi) {
        return std::clamp(int(std::floor(p * per_cell)), lo, hi);
    };
    int ix = cell(r.o.x + t0 * r.d.x, x_lo, x_hi), iz = cell(r.o.z + t0 * r.d.z, z_lo, z_hi);
    const int sx = r.d.x > 0 ? 1 : r.d.x < 0 ? -1 : 0, sz = r.d.z > 0 ? 1 : r.d.z < 0 ? -1 : 0;
    auto next_boundary = [&](int i, int step, double o, double inv) {
        return step == 0 ? inf : ((i + (step > 0)) * size - o) * inv;
    };
    double tx = next_boundary(ix, sx, r.o.x, r.inv_x), tz = next_boundary(iz, sz, r.o.z, r.inv_z);
    const double dtx = sx ? size * std::abs(r.inv_x) : inf, dtz = sz ? size * std::abs(r.inv_z) : inf;
    double ta = t0;
    const int steps = (x_hi - x_lo) + (z_hi - z_lo) + 2;
    for (int k = 0; k < steps; ++k) {
        const double tb = std::max(ta, std::min({tx, tz, t1}));
        if (visit(ix, iz, ta, tb)) return true;
        if (tb >= t1) return false;
        if (tx < tz) {
            ix += sx, ta = tb, tx += dtx;
            if (ix < x_lo || ix > x_hi) return false;
        } else {
            iz += sz, ta = tb, tz += dtz;
            if (iz < z_lo || iz > z_hi) return false;
        }
    }
    return false;
}

// Whether the ray's height between ta and tb can meet heights in [lo, hi].
bool heights_overlap(const GridRay& r, double ta, double tb, double lo, double hi) {
    const double ya = r.y(ta), yb = r.y(tb);
    return std::min(ya, yb) <= hi + 1e-6 && std::max(ya, yb) >= lo - 1e-6;
}

struct CellHit {
    double t;
    glm::dvec3 normal;  // grid units
};

// The plane through p0 with normal n, if the ray meets it at a depth in [t0, t1].
bool plane_depth(const GridRay& r, const glm::dvec3& p0, const glm::dvec3& n, double t0,
                 double t1, double& t) {
    const double nd = glm::dot(n, r.d);
    if (std::abs(nd) <= kEps) return false;
    t = glm::dot(n, p0 - r.o) / nd;
    return t >= t0 && t <= t1;
}

// The nearer triangle hit of cell (x, z) at a depth in (tmin, ...] within [t0, t1].
bool hit_cell(const HeightFieldShape& s, const GridRay& r, int x, int z, double t0, double t1,
              double tmin, CellHit& out) {
    const double y1 = s.at(x, z), y2 = s.at(x + 1, z), y3 = s.at(x, z + 1), y4 = s.at(x + 1, z + 1);
    bool found = false;
    auto consider = [&](double t, const glm::dvec3& n) {
        if (t <= tmin || (found && t >= out.t)) return;
        out = {t, n};
        found = true;
    };
    double t;
    const glm::dvec3 n1(y1 - y2, 1, y1 - y3);
    if (plane_depth(r, {x, y1, z}, n1, t0, t1, t)) {
        const double a = r.o.x + t * r.d.x - x, b = r.o.z + t * r.d.z - z;
        if (a >= -kSideTolerance && b >= -kSideTolerance && a + b <= 1 + kSideTolerance)
            consider(t, n1);
    }
    const glm::dvec3 n2(y3 - y4, 1, y2 - y4);
    if (plane_depth(r, {x + 1, y4, z + 1}, n2, t0, t1, t)) {
        const double a = r.o.x + t * r.d.x - x, b = r.o.z + t * r.d.z - z;
        if (a <= 1 + kSideTolerance && b <= 1 + kSideTolerance && a + b >= 1 - kSideTolerance)
            consider(t, n2);
    }
    return found;
}

// The vertex normals of a smooth field, in grid units: the normalised sum of the unit normals
// of the fan triangles around the vertex that lie in the grid, each turned upward, stored as
// int(32767 n) per component.
std::vector<std::array<int16_t, 3>> vertex_normals(const HeightFieldShape& s) {
    std::vector<std::array<int16_t, 3>> out(size_t(s.columns) * size_t(s.rows));
    auto vertex = [&](int x, int z) { return glm::dvec3(x, s.at(x, z), z); };
    auto in_grid = [&](int x, int z) { return x >= 0 && z >= 0 && x < s.columns && z < s.rows; };
    static constexpr int kFan[4][4] = {{1, 0, 0, 1}, {0, 1, -1, 0}, {-1, 0, 0, -1}, {0, -1, 1, 0}};
    for (int z = 0; z < s.rows; ++z)
        for (int x = 0; x < s.columns; ++x) {
            glm::dvec3 sum(0);
            const glm::dvec3 v0 = vertex(x, z);
            for (const auto& f : kFan) {
                if (!in_grid(x + f[0], z + f[1]) || !in_grid(x + f[2], z + f[3])) continue;
                const glm::dvec3 v1 = vertex(x + f[0], z + f[1]), v2 = vertex(x + f[2], z + f[3]);
                glm::dvec3 n = glm::normalize(glm::cross(v2 - v0, v1 - v0));
                if (n.y < 0) n = -n;
                sum += n;
            }
            const glm::dvec3 n = glm::normalize(sum);
            out[size_t(z) * size_t(s.columns) + size_t(x)] = {int16_t(32767 * n.x), int16_t(32767 * n.y),
                                                              int16_t(32767 * n.z)};
        }
    return out;
}

// The smooth normal at grid point p in the space rays arrive in: the four stored corner
// normals of its cell each taken there and normalised, blended bilinearly, normalised.
glm::dvec3 smooth_normal(const HeightFieldShape& s, const glm::dvec3& p) {
    const int px = std::clamp(int(p.x), 0, s.columns - 2), pz = std::clamp(int(p.z), 0, s.rows - 2);
    const double fx = p.x - px, fz = p.z - pz;
    auto corner = [&](int x, int z) {
        const auto& q = s.normals[size_t(z) * size_t(s.columns) + size_t(x)];
        const glm::dvec3 n = s.grid_to_space.normal({q[0], q[1], q[2]});
        const double len = glm::length(n);
        return len > 0 ? n / len : n;
    };
    const glm::dvec3 n = (1 - fz) * ((1 - fx) * corner(px, pz) + fx * corner(px + 1, pz)) +
                         fz * ((1 - fx) * corner(px, pz + 1) + fx * corner(px + 1, pz + 1));
    const double len = glm::length(n);
    return len > 0 ? n / len : s.grid_to_space.normal({0, 1, 0});
}

// The height ranges of the cells (their four corners), then of blocks of 8 x 8 of the level
// below, until a level has at most 8 x 8 blocks (8 took the fewest instructions of 4, 8, 16).
std::vector<HeightFieldShape::Level> range_pyramid(const HeightFieldShape& s) {
    std::vector<HeightFieldShape::Level> levels(1);
    HeightFieldShape::Level& cells = levels[0];
    cells.columns = s.columns - 1;
    cells.rows = s.rows - 1;
    cells.range.resize(size_t(cells.columns) * size_t(cells.rows));
    for (int z = 0; z < cells.rows; ++z)
        for (int x = 0; x < cells.columns; ++x) {
            const auto [lo, hi] = std::minmax({s.at(x, z), s.at(x + 1, z), s.at(x, z + 1), s.at(x + 1, z + 1)});
            cells.range[size_t(z) * size_t(cells.columns) + size_t(x)] = {uint16_t(lo), uint16_t(hi)};
        }
    constexpr int kFanOut = 8;
    while (levels.back().columns > kFanOut || levels.back().rows > kFanOut) {
        const HeightFieldShape::Level& below = levels.back();
        HeightFieldShape::Level up;
        up.size = below.size * kFanOut;
        up.columns = (below.columns + kFanOut - 1) / kFanOut;
        up.rows = (below.rows + kFanOut - 1) / kFanOut;
        up.range.assign(size_t(up.columns) * size_t(up.rows), {65535, 0});
        for (int z = 0; z < below.rows; ++z)
            for (int x = 0; x < below.columns; ++x) {
                const auto& from = below.range[size_t(z) * size_t(below.columns) + size_t(x)];
                auto& to = up.range[size_t(z / kFanOut) * size_t(up.columns) + size_t(x / kFanOut)];
                to = {std::min(to[0], from[0]), std::max(to[1], from[1])};
            }
        levels.push_back(std::move(up));
    }
    return levels;
}

// One ray's descent through the pyramid: a block the ray's heights can meet is walked at the
// level below, down to the cells, whose triangles are tested; the first cell with a hit ends
// the search.
struct Descent {
    const HeightFieldShape& s;
    const GridRay& r;
    double t0, t1, tmin;
    CellHit& hit;

    bool enter(int level, int bx, int bz, double ta, double tb) const {
        const HeightFieldShape::Level& lv = s.levels[size_t(level)];
        const auto& range = lv.range[size_t(bz) * size_t(lv.columns) + size_t(bx)];
        if (!heights_overlap(r, ta, tb, range[0], range[1])) return false;
        if (level == 0) return hit_cell(s, r, bx, bz, t0, t1, tmin, hit);
        const HeightFieldShape::Level& below = s.levels[size_t(level) - 1];
        const int ratio = lv.size / below.size;
        const int x_lo = bx * ratio, z_lo = bz * ratio;
        return walk(r, below.size, x_lo, std::min(x_lo + ratio - 1, below.columns - 1), z_lo,
                    std::min(z_lo + ratio - 1, below.rows - 1), ta, tb,
                    [&](int x, int z, double a, double b) { return enter(level - 1, x, z, a, b); });
    }
};

}  // namespace

std::unique_ptr<HeightFieldShape> make_height_field(const scene::HeightField& hf,
                                                    const scene::Transform& to_space) {
    auto s = std::make_unique<HeightFieldShape>();
    s->heights = hf.heights;
    s->columns = hf.columns;
    s->rows = hf.rows;
    if (!hf.heights || hf.columns < 2 || hf.rows < 2 ||
        hf.heights->size() != size_t(hf.columns) * size_t(hf.rows) || !std::isfinite(hf.water_level))
        return s;
    const glm::dvec3 scale(1.0 / (hf.columns - 1), 1.0 / 65536.0, 1.0 / (hf.rows - 1));
    scene::Transform grid;
    grid.m = glm::dmat4(glm::dvec4(scale.x, 0, 0, 0), glm::dvec4(0, scale.y, 0, 0),
                        glm::dvec4(0, 0, scale.z, 0), glm::dvec4(0, 0, 0, 1));
    grid.inv = glm::dmat4(glm::dvec4(1 / scale.x, 0, 0, 0), glm::dvec4(0, 1 / scale.y, 0, 0),
                          glm::dvec4(0, 0, 1 / scale.z, 0), glm::dvec4(0, 0, 0, 1));
    s->grid_to_space = grid.then(to_space);
    const auto [lo, hi] = std::minmax_element(hf.heights->begin(), hf.heights->end());
    s->water = 65536.0 * hf.water_level;
    s->floor = std::max(double(*lo), s->water) - 0.001;
    s->top = *hi + 0.001;
    s->levels = range_pyramid(*s);
    s->smooth = hf.smooth;
    if (s->smooth) s->normals = vertex_normals(*s);
    s->valid = true;
    return s;
}

bool intersect(const HeightFieldShape& s, const LocalRay& ray, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const GridRay r{s.grid_to_space.inv_point(ray.o), s.grid_to_space.inv_vector(ray.d)};
    if (!std::isfinite(r.inv_x) || !std::isfinite(r.inv_z)) return false;
    const Aabb box{{0, s.floor, 0}, {double(s.columns - 1), s.top, double(s.rows - 1)}};
    double t0, t1;
    if (!SlabRay(r.o, r.d).hits(box, -Aabb::inf, Aabb::inf, t0, t1)) return false;
    t0 = std::max(t0, kDepthDefault);  // POV-Ray raises the box entry to its minimum depth
    t1 = std::min(t1, tmax);
    const double from = std::max(t0, tmin);
    if (!(from <= t1)) return false;
    CellHit hit{};
    const HeightFieldShape::Level& top = s.levels.back();
    Descent descent{s, r, t0, t1, tmin, hit};
    if (!walk(r, top.size, 0, top.columns - 1, 0, top.rows - 1, from, t1,
              [&](int bx, int bz, double ta, double tb) {
                  return descent.enter(int(s.levels.size()) - 1, bx, bz, ta, tb);
              }))
        return false;
    h.t = hit.t;
    h.normal = s.smooth ? smooth_normal(s, r.o + hit.t * r.d) : s.grid_to_space.normal(hit.normal);
    h.uv = {0, 0};
    h.texture = nullptr;
    return true;
}

// Outside the grid's x-z range or above the box: outside; below the water level: inside;
// else inside when below the triangle over the point. There is no floor: the solid reaches
// down without end (measured: a sphere's far side below the lowest height shows through
// the difference of a field and the sphere). A cylinder clipped by a field does end in
// POV-Ray (objects/csg/hfclip.pov), but only because POV-Ray bounds the clipped object by
// the field's box, which lumen does not.
bool inside(const HeightFieldShape& s, const glm::dvec3& point) {
    if (!s.valid) return false;
    const glm::dvec3 p = s.grid_to_space.inv_point(point);
    if (!(p.x >= 0 && p.z >= 0 && p.x <= s.columns - 1 && p.z <= s.rows - 1) || p.y > s.top)
        return false;
    if (p.y < s.water) return true;
    const int x = std::min(int(p.x), s.columns - 2), z = std::min(int(p.z), s.rows - 2);
    const double a = p.x - x, b = p.z - z;
    const double y1 = s.at(x, z), y2 = s.at(x + 1, z), y3 = s.at(x, z + 1), y4 = s.at(x + 1, z + 1);
    const double surface = a + b <= 1 ? y1 + (y2 - y1) * a + (y3 - y1) * b
                                      : y4 + (y4 - y3) * (a - 1) + (y4 - y2) * (b - 1);
    return p.y < surface;
}

namespace {

Aabb grid_box(const HeightFieldShape& s, double y0, double y1) {
    if (!s.valid || y0 > y1) return {};
    Aabb out;
    for (int i = 0; i < 8; ++i)
        out.expand(s.grid_to_space.point({(i & 1) ? s.columns - 1.0 : 0.0, (i & 2) ? y1 : y0,
                                          (i & 4) ? s.rows - 1.0 : 0.0}));
    return out;
}

}  // namespace

Aabb bounds(const HeightFieldShape& s) { return grid_box(s, s.floor, s.top); }
// The box and the column below it.
Aabb solid_bounds(const HeightFieldShape& s) {
    Aabb out = bounds(s);
    if (out.empty()) return out;
    const glm::dvec3 down = s.grid_to_space.vector({0, -1, 0});
    for (int a = 0; a < 3; ++a) {
        if (down[a] < 0) out.lo[a] = -Aabb::inf;
        if (down[a] > 0) out.hi[a] = Aabb::inf;
    }
    return out;
}

}  // namespace lumen::render

// Patch construction, sampling, subdivision and ray crossing.
#include "render/radiosity/patch.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace lumen::render::radiosity {

Patch make_patch(std::vector<glm::dvec3> vertices, glm::dvec3 rho, glm::dvec3 emission,
                 int object) {
    Patch p;
    p.vertices = std::move(vertices);
    p.rho = rho;
    p.emission = emission;
    p.object = object;
    const size_t n = p.vertices.size();
    if (n == 0) return p;
    // Newell's normal: twice the vector area; robust for near-planar polygons.
    glm::dvec3 twice_area(0);
    glm::dvec3 mean(0);
    for (size_t i = 0; i < n; ++i) {
        twice_area += glm::cross(p.vertices[i], p.vertices[(i + 1) % n]);
        mean += p.vertices[i];
    }
    mean /= double(n);
    const double len = glm::length(twice_area);
    p.area = 0.5 * len;
    if (!(len > 1e-300) || !std::isfinite(len)) {
        p.area = 0;
        p.centroid = mean;
        return p;
    }
    p.normal = twice_area / len;
    // Area centroid from the fan around the vertex mean.
    glm::dvec3 c(0);
    double wsum = 0;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& a = p.vertices[i];
        const glm::dvec3& b = p.vertices[(i + 1) % n];
        const double w = glm::dot(glm::cross(a - mean, b - mean), p.normal);
        c += w * (mean + a + b) / 3.0;
        wsum += w;
    }
    p.centroid = wsum > 0 ? c / wsum : mean;
    return p;
}

Patch part_of(const Patch& whole, std::vector<glm::dvec3> vertices) {
    Patch p = make_patch(std::move(vertices), whole.rho, whole.emission, whole.object);
    p.texture = whole.texture;
    return p;
}

Patch flipped(const Patch& p) { return part_of(p, {p.vertices.rbegin(), p.vertices.rend()}); }

namespace {

double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

glm::dvec3 sample_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                           double u1, double u2) {
    const double s = std::sqrt(u1);
    return (1 - s) * a + s * (1 - u2) * b + s * u2 * c;
}

}  // namespace

glm::dvec3 sample_point(const Patch& p, double u1, double u2) {
    const size_t n = p.vertices.size();
    if (n < 3 || p.degenerate()) return p.centroid;
    // Pick a fan triangle by area with u1, then rescale u1 to reuse it inside the triangle.
    double total = 0;
    for (size_t i = 1; i + 1 < n; ++i)
        total += triangle_area(p.vertices[0], p.vertices[i], p.vertices[i + 1]);
    double target = u1 * total;
    for (size_t i = 1; i + 1 < n; ++i) {
        const double a = triangle_area(p.vertices[0], p.vertices[i], p.vertices[i + 1]);
        if (target < a || i + 2 == n) {
            const double u = a > 0 ? std::clamp(target / a, 0.0, 1.0) : 0.5;
            return sample_triangle(p.vertices[0], p.vertices[i], p.vertices[i + 1], u, u2);
        }
        target -= a;
    }
    return p.centroid;
}

namespace {

int pieces(double length, double max_edge) {
    return std::max(1, int(std::ceil(length / max_edge - 1e-9)));
}

// Pieces along a quad's long side are at most this many times as long as the quad is wide:
// a long thin face (the 0.1-high sides of radiosity/patio-radio_37.pov's 980-long paving
// slabs) cut only by the patch size gave elements that mesh_checks reports as slivers (over
// 500 : 1), of lumen's own making. Half that ratio, and at most 4096 pieces.
constexpr double kMaxAspect = 250;

void subdivide_quad(const Patch& p, double max_edge, std::vector<Patch>& out) {
    const auto& v = p.vertices;
    const double lu = std::max(glm::length(v[1] - v[0]), glm::length(v[2] - v[3]));
    const double lw = std::max(glm::length(v[3] - v[0]), glm::length(v[2] - v[1]));
    int m = pieces(lu, max_edge);
    int n = pieces(lw, max_edge);
    if (lw > 0 && lu / m > kMaxAspect * lw / n)
        m = std::min(4096, std::max(m, pieces(lu, kMaxAspect * lw / n)));
    if (lu > 0 && lw / n > kMaxAspect * lu / m)
        n = std::min(4096, std::max(n, pieces(lw, kMaxAspect * lu / m)));
    auto at = [&](int i, int j) {
        const double s = double(i) / m, t = double(j) / n;
        return (1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] + s * t * v[2] + (1 - s) * t * v[3];
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < m; ++i)
            out.push_back(part_of(p, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}));
}

void subdivide_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                        const Patch& p, double max_edge, std::vector<Patch>& out) {
    const double longest =
        std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const int k = pieces(longest, max_edge);
    auto at = [&](int i, int j) {  // barycentric grid point: i steps toward b, j toward c
        return a + (double(i) / k) * (b - a) + (double(j) / k) * (c - a);
    };
    for (int j = 0; j < k; ++j)
        for (int i = 0; i + j < k; ++i) {
            out.push_back(part_of(p, {at(i, j), at(i + 1, j), at(i, j + 1)}));
            if (i + j + 1 < k) out.push_back(part_of(p, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}));
        }
}

}  // namespace

std::vector<Patch> subdivide(const Patch& p, double max_edge) {
    std::vector<Patch> out;
    if (!(max_edge > 0) || p.vertices.size() < 3) {
        out.push_back(p);
        return out;
    }
    if (p.vertices.size() == 4) {
        subdivide_quad(p, max_edge, out);
    } else {
        for (size_t i = 1; i + 1 < p.vertices.size(); ++i)
            subdivide_triangle(p.vertices[0], p.vertices[i], p.vertices[i + 1], p, max_edge, out);
    }
    return out;
}

double intersect(const Patch& p, const glm::dvec3& origin, const glm::dvec3& dir,
                 double t_min) {
    if (p.degenerate()) return -1;
    const double denom = glm::dot(p.normal, dir);
    if (std::abs(denom) < 1e-300) return -1;
    const double t = glm::dot(p.normal, p.vertices[0] - origin) / denom;
    if (!(t > t_min)) return -1;
    const glm::dvec3 x = origin + t * dir;
    // Convex polygon: the point must lie on the inner side of every edge (edges included).
    const size_t n = p.vertices.size();
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3& a = p.vertices[i];
        const glm::dvec3& b = p.vertices[(i + 1) % n];
        if (glm::dot(glm::cross(b - a, x - a), p.normal) < 0) return -1;
    }
    return t;
}

double total_area(const std::vector<Patch>& patches) {
    double a = 0;
    for (const auto& p : patches) a += p.area;
    return a;
}

}  // namespace lumen::render::radiosity

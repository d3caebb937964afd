#include "render/shapes/container.hpp"

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

namespace lumen::render {

bool container_span(const scene::Container& c, const LocalRay& r, double len, double& t1,
                    double& t2, glm::dvec3& n1, glm::dvec3& n2) {
    if (c.sphere) {
        const glm::dvec3 d = r.d / len, oc = r.o - c.center;
        const double b = glm::dot(oc, d), k = glm::dot(oc, oc) - c.radius * c.radius;
        const double disc = b * b - k;
        if (!(disc >= 0)) return false;
        const double q = std::sqrt(disc);
        t1 = (-b - q) / len;
        t2 = (-b + q) / len;
        n1 = glm::normalize(r.at(t1) - c.center);
        n2 = glm::normalize(r.at(t2) - c.center);
        return t2 >= 1e-6;
    }
    t1 = 0;
    t2 = kFar;
    n1 = n2 = glm::dvec3(0);
    for (int a = 0; a < 3; ++a) {
        if (r.d[a] == 0) {
            if (r.o[a] < c.lo[a] || r.o[a] > c.hi[a]) return false;
            continue;
        }
        double ta = (c.lo[a] - r.o[a]) / r.d[a], tb = (c.hi[a] - r.o[a]) / r.d[a];
        glm::dvec3 na(0), nb(0);
        na[a] = -1;
        nb[a] = 1;
        if (ta > tb) std::swap(ta, tb), std::swap(na, nb);
        if (ta > t1) t1 = ta, n1 = na;
        if (tb < t2) t2 = tb, n2 = nb;
        if (t1 > t2) return false;
    }
    return t2 >= 1e-6;
}

bool in_container(const scene::Container& c, const glm::dvec3& p) {
    if (c.sphere) {
        const glm::dvec3 d = p - c.center;
        return glm::dot(d, d) <= c.radius * c.radius;
    }
    return p.x >= c.lo.x && p.y >= c.lo.y && p.z >= c.lo.z && p.x <= c.hi.x && p.y <= c.hi.y &&
           p.z <= c.hi.z;
}

Aabb container_bounds(const scene::Container& c) { return {c.box_min(), c.box_max()}; }

}  // namespace lumen::render

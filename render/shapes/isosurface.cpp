#include "render/shapes/isosurface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <glm/geometric.hpp>

#include "render/function_host.hpp"
#include "render/shapes/container.hpp"

namespace lumen::render {

namespace {

// The function at object-space point p.
double F(const IsosurfaceShape& s, const glm::dvec3& p) {
    const double a[3] = {p.x, p.y, p.z};
    return fn::evaluate(*s.iso.function, a, s.context);
}

// POV-Ray's cross-ray cache, one per render thread: the ends and the lowest value of the last
// failed root search of a non-shadow ray. A later search on the same object whose ends lie
// near enough that the gradient bound keeps the function above zero is skipped. With a
// max_gradient that holds this changes nothing but the time; with one too low it decides, as
// in POV-Ray, some of the holes.
struct FailedSearch {
    uint64_t object = 0;  // the shape's id; 0: empty
    glm::dvec3 p1{0}, p2{0};
    double fmin = 0;
};
thread_local FailedSearch t_failed;
thread_local bool t_shadow_ray = false;

// One ray's search: the function along the ray and the gradient bound in use.
struct Search {
    const IsosurfaceShape& s;
    const LocalRay& r;
    double len;       // |d|
    double g;         // max_gradient (raised by `evaluate`)
    double sign = 1;  // +1: looking for V < 0 (entering); -1: for V > 0
    double found = 0;  // the steepest |f(b) - f(a)| per object-space unit met
    double fmin = 0;   // the lowest f met by the current root search
    // The function's last few values along this ray. The algorithm asks again for points it
    // has just evaluated (the container's ends, a root for its normal); the function is pure,
    // so a value looked up here is the value an evaluation would give.
    struct Known {
        double t = std::nan(""), F = 0;
    };
    Known known[4] = {};
    unsigned next = 0;

    double Fat(double t) {
        for (const Known& k : known)
            if (k.t == t) return k.F;
        const double v = F(s, r.at(t));
        known[next++ & 3] = {t, v};
        return v;
    }
    double V(double t) { return Fat(t) - s.iso.threshold; }
    double f(double t) { return sign * V(t); }

    // POV's recursive bisection: an interval is split while the ends' values and the gradient
    // bound allow a root inside; the depth is the far end of the first leaf (narrower than the
    // accuracy) whose end value is negative.
    bool bisect(double ta, double fa, double tb, double fb, double dt, double w, double inv,
                double& root) {
        const double slope = std::fabs(fb - fa) * inv;
        found = std::max(found, slope);
        if (s.iso.evaluate) {
            const glm::dvec3 e = *s.iso.evaluate;
            if (g < slope * e.y) {
                g = slope * e.y * e.y;
                dt = g * len * w;
            }
        }
        if (w < s.iso.accuracy) {
            if (fb < 0) {
                root = tb;
                return true;
            }
            return false;
        }
        if (fa + fb - dt < 0) {
            w /= 2;
            dt /= 2;
            const double tm = ta + w, fm = f(tm);
            fmin = std::min(fmin, fm);
            return bisect(ta, fa, tm, fm, dt, w, 2 * inv, root) ||
                   bisect(tm, fm, tb, fb, dt, w, 2 * inv, root);
        }
        return false;
    }

    bool find_root(double t1, double t2, double& root) {
        const glm::dvec3 p1 = r.at(t1), p2 = r.at(t2);
        const uint64_t object = s.id;
        if (t_failed.object == object) {
            const double reach = std::max(glm::length(p1 - t_failed.p1), glm::length(p2 - t_failed.p2));
            if (t_failed.fmin - g * reach > 0) return false;
        }
        t_failed.object = 0;
        double f1 = f(t1);
        fmin = f1;
        if (s.iso.open && f1 < 0) {  // an open surface looks for the exit instead
            sign = -sign;
            f1 = -f1;
        }
        const double f2 = f(t2);
        fmin = std::min(fmin, f2);
        if (s.iso.evaluate && g > s.iso.evaluate->x) g *= s.iso.evaluate->z;
        const double w = t2 - t1;
        if (bisect(t1, f1, t2, f2, g * len * w, w, 1 / (len * w), root)) return true;
        if (!t_shadow_ray) t_failed = {object, p1, p2, fmin};
        return false;
    }
};

// The normal at object-space point p, where the function's value is f0.
glm::dvec3 function_normal(const IsosurfaceShape& s, const glm::dvec3& p, double f0) {
    const scene::Isosurface& iso = s.iso;
    const scene::Container& c = iso.container;
    if (c.sphere && std::fabs(glm::length(p - c.center) - c.radius) < 1e-10)
        return glm::normalize(p - c.center);
    const double A = iso.accuracy;
    const glm::dvec3 n(F(s, p + glm::dvec3(A, 0, 0)) - f0, F(s, p + glm::dvec3(0, A, 0)) - f0,
                       F(s, p + glm::dvec3(0, 0, A)) - f0);
    if (n == glm::dvec3(0)) return {1, 0, 0};
    const glm::dvec3 u = glm::normalize(n);
    return std::isfinite(u.x + u.y + u.z) ? u : glm::dvec3(1, 0, 0);
}

}  // namespace

ShadowRayMark::ShadowRayMark(bool shadow) : previous_(t_shadow_ray) { t_shadow_ray = shadow; }
ShadowRayMark::~ShadowRayMark() { t_shadow_ray = previous_; }

IsosurfaceShape make_isosurface(const scene::Isosurface& s) {
    static std::atomic<uint64_t> next_id{1};
    IsosurfaceShape out;
    out.id = next_id.fetch_add(1, std::memory_order_relaxed);
    out.iso = s;
    if (s.globals) out.context.noise_generator = s.globals->noise_generator;
    out.context.host = &function_host();
    out.valid = bool(s.function) && s.function->params == 3;
    return out;
}

int isosurface_hits(const IsosurfaceShape& s, const LocalRay& r, IsoHit* hits) {
    if (!s.valid) return 0;
    const scene::Isosurface& iso = s.iso;
    const double len = glm::length(r.d);
    if (!(len > 0)) return 0;
    double t1, t2;
    glm::dvec3 n1, n2;
    if (!container_span(iso.container, r, len, t1, t2, n1, n2)) return 0;
    t1 = std::max(t1, 0.0);
    const double A = iso.accuracy;
    Search search{s, r, len, iso.max_gradient};
    int n = 0, count = 0;
    auto record = [&](double t, const glm::dvec3& normal) {
        if (count < kMaxIsoHits) hits[count++] = {t, normal};
    };
    if (!iso.open) {
        const double v0 = search.V(t1);
        if (t1 > A) {  // the ray enters the container: inside the solid there, a cut face
            if (v0 < 0) {
                record(t1, n1);
                n = 1;
                search.sign = -1;
            }
        } else {  // it starts inside the container
            if (v0 < 4 * search.g * A) {
                t1 = 5 * A;
                if (search.V(t1) < 0) search.sign = -1;
            }
            if (search.V(t2) < 0) record(t2, n2);
        }
    }
    t2 = std::min(t2, kFar);
    t1 = std::min(t1, t2);
    if (t2 - t1 < A) {
        if (count > 0) --count;
        return count;
    }
    if (t1 < A && search.sign > 0 && std::fabs(search.V(t1)) < 4 * search.g * A) {
        t1 = 5 * A;
        if (search.V(t1) < 0) search.sign = -1;
    }
    while (n < iso.max_trace) {
        double root;
        if (!search.find_root(t1, t2, root)) break;
        record(root, function_normal(s, r.at(root), search.Fat(root)));
        t1 = root + 5 * A;
        if (t2 - t1 < A) break;
        search.sign = -search.sign;
        ++n;
    }
    std::sort(hits, hits + count, [](const IsoHit& a, const IsoHit& b) { return a.t < b.t; });
    // One shared update per ray, and only when the ray met a steeper slope.
    std::atomic<double>& shared = *s.gradient_found;
    double seen = shared.load(std::memory_order_relaxed);
    while (search.found > seen &&
           !shared.compare_exchange_weak(seen, search.found, std::memory_order_relaxed)) {
    }
    return count;
}

std::optional<std::string> gradient_warning(const IsosurfaceShape& s) {
    const double found = s.gradient_found->load(std::memory_order_relaxed);
    const double G = s.iso.max_gradient;
    if (s.iso.evaluate || !(found > 1e-10) || !(G > 1e-10)) return std::nullopt;
    const double diff = G - found, prop = std::fabs(G / found);
    char text[256];
    if ((prop <= 0.9 && diff <= -0.5) || ((prop <= 0.95 || diff <= -0.1) && G < 10)) {
        std::snprintf(text, sizeof text,
                      "The maximum gradient found was %0.3f, but max_gradient of the isosurface was "
                      "set to %0.3f. The isosurface may contain holes! Adjust max_gradient to get a "
                      "proper rendering of the isosurface.", found, G);
        return std::string(text);
    }
    if (diff >= 10 || (prop >= 1.1 && diff >= 0.5)) {
        std::snprintf(text, sizeof text,
                      "The maximum gradient found was %0.3f, but max_gradient of the isosurface was "
                      "set to %0.3f. Adjust max_gradient to get a faster rendering of the isosurface.",
                      found, G);
        return std::string(text);
    }
    return std::nullopt;
}

bool intersect(const IsosurfaceShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    IsoHit hits[kMaxIsoHits];
    const int count = isosurface_hits(s, r, hits);
    for (int i = 0; i < count; ++i)
        if (hits[i].t > tmin && hits[i].t < tmax) {
            h.t = hits[i].t;
            h.normal = hits[i].normal;
            return true;
        }
    return false;
}

bool inside(const IsosurfaceShape& s, const glm::dvec3& p) {
    if (!s.valid) return false;
    return in_container(s.iso.container, p) && F(s, p) <= s.iso.threshold;
}

Aabb bounds(const IsosurfaceShape& s) { return container_bounds(s.iso.container); }

}  // namespace lumen::render

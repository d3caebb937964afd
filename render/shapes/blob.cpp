// blob: POV-Ray's interval sweep. Its tolerances decide which grazing rays hit and where the
// surface starts near the ray origin, so they are POV-Ray's: elements are entered where the
// ray's discriminant reaches 1e-10, hits nearer than 1e-2 are ignored, the solver drops a
// root at 0 below 1e-11, and a point is inside where the density exceeds threshold - 1e-6.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "render/pov_polynomial.hpp"
#include "render/shapes/blob.hpp"

namespace lumen::render {

namespace {

constexpr double kEpsilon = 1e-10;
constexpr double kSmallTolerance = 1e-3;  // the ray start moves to the first entry beyond it
constexpr double kRootTolerance = 1e-11;
constexpr double kInsideTolerance = 1e-6;
constexpr double kMaxDistance = 1e7;
constexpr int kLeafSize = 2;
constexpr double kHuge = std::numeric_limits<double>::infinity();

using Kind = BlobElement::Kind;

glm::dvec3 to_element(const BlobShape& s, const BlobElement& e, const glm::dvec3& p) {
    return e.transform < 0 ? p : s.to_component[e.transform].inv_point(p);
}
glm::dvec3 to_element_dir(const BlobShape& s, const BlobElement& e, const glm::dvec3& d) {
    return e.transform < 0 ? d : s.to_component[e.transform].inv_vector(d);
}

// The vector from the element's nearest centre or axis point to q (element space), and
// whether q is in the element's part of space (a cap's half, the cylinder's length). The
// parts share their boundary planes, as in POV-Ray: a point exactly level with a cylinder's
// end gets the density of both (a box face there shows a wider cut, measured).
bool element_offset(const BlobElement& e, const glm::dvec3& q, glm::dvec3& v) {
    v = q - e.centre;
    if (e.kind == Kind::Sphere) return true;
    const double z = glm::dot(v, e.axis);
    switch (e.kind) {
        case Kind::Cylinder:
            if (z < 0 || z > e.length) return false;
            v -= z * e.axis;
            return true;
        case Kind::BaseCap: return z <= 0;
        case Kind::ApexCap:
            if (z < e.length) return false;
            v -= e.length * e.axis;
            return true;
        default: return true;
    }
}

// Where the ray o + t d (element space, d not unit) is inside the element: [t0, t1].
bool element_interval(const BlobElement& e, const glm::dvec3& o, const glm::dvec3& d,
                      double& t0, double& t1) {
    glm::dvec3 v = o - e.centre;
    if (e.kind == Kind::ApexCap) v -= e.length * e.axis;
    glm::dvec3 dv = d;
    const double vz = glm::dot(v, e.axis), dz = glm::dot(d, e.axis);
    if (e.kind == Kind::Cylinder) {  // the infinite cylinder first: distances across the axis
        v -= vz * e.axis;
        dv -= dz * e.axis;
    }
    const double a = glm::dot(dv, dv), b = glm::dot(v, dv), c = glm::dot(v, v) - e.rad2;
    if (e.kind == Kind::Cylinder && a < kEpsilon) {  // along the axis
        if (c >= 0) return false;
        t0 = -std::numeric_limits<double>::infinity();
        t1 = std::numeric_limits<double>::infinity();
    } else {
        if (!(a > 0)) return false;
        const double disc = b * b - a * c;
        if (disc < kEpsilon) return false;
        const double root = std::sqrt(disc);
        t0 = (-b - root) / a;
        t1 = (-b + root) / a;
    }
    if (e.kind == Kind::Sphere) return true;
    // The part of space the element owns along the axis: z < 0 (base cap), 0..len
    // (cylinder), z > 0 past the apex (apex cap); z(t) = vz + t dz.
    double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
    if (e.kind == Kind::BaseCap) hi = 0;
    else if (e.kind == Kind::ApexCap) lo = 0;
    else { lo = 0; hi = e.length; }
    if (std::fabs(dz) < kEpsilon) {
        if (vz < lo || vz > hi) return false;
    } else {
        double za = (lo - vz) / dz, zb = (hi - vz) / dz;
        if (za > zb) std::swap(za, zb);
        t0 = std::max(t0, za);
        t1 = std::min(t1, zb);
    }
    return t0 < t1;
}

// The element's density along o + t d as a quartic in t, lowest power first.
void element_quartic(const BlobElement& e, const glm::dvec3& o, const glm::dvec3& d,
                     double* q) {
    glm::dvec3 v = o - e.centre, dv = d;
    if (e.kind == Kind::ApexCap) v -= e.length * e.axis;
    if (e.kind == Kind::Cylinder) {
        v -= glm::dot(v, e.axis) * e.axis;
        dv -= glm::dot(dv, e.axis) * e.axis;
    }
    const double t0 = glm::dot(v, v), t1 = glm::dot(v, dv), t2 = glm::dot(dv, dv);
    const double c0 = e.c[0], c1 = e.c[1], c2 = e.c[2];
    q[4] = c0 * t2 * t2;
    q[3] = 4 * c0 * t1 * t2;
    q[2] = 2 * c0 * (2 * t1 * t1 + t0 * t2) + c1 * t2;
    q[1] = 2 * t1 * (2 * c0 * t0 + c1);
    q[0] = t0 * (c0 * t0 + c1) + c2;
}

// True when the quartic (lowest power first) may vanish for t in [l, l + w]: the Bernstein
// coefficients of its restriction to the piece do not all have one sign.
bool may_have_root(const double* a, double l, double w) {
    // q(s) = a(l + w s), lowest power first.
    static constexpr double kBinomial[5][5] = {
        {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
    double q[5];
    double wk = 1;
    for (int k = 0; k <= 4; ++k) {
        double sum = 0, lp = 1;
        for (int j = k; j <= 4; ++j) {
            sum += kBinomial[j][k] * a[j] * lp;
            lp *= l;
        }
        q[k] = sum * wk;
        wk *= w;
    }
    bool positive = false, negative = false;
    for (int i = 0; i <= 4; ++i) {
        double b = 0;
        for (int k = 0; k <= i; ++k) b += kBinomial[i][k] / kBinomial[4][k] * q[k];
        positive |= b >= 0;
        negative |= b <= 0;
    }
    return positive && negative;
}

// One Newton step on the quartic (lowest power first) from root x, kept when it stays in the
// piece and brings the value nearer 0. The closed-form quartic is good to about 1e-7 of the
// events' span; the step takes that to rounding without moving any root a pixel would see.
double polished(const double* a, double x, double l, double w) {
    auto value = [&](double t, double& slope) {
        double v = a[4], dv = 0;
        for (int k = 3; k >= 0; --k) {
            dv = dv * t + v;
            v = v * t + a[k];
        }
        slope = dv;
        return v;
    };
    double slope;
    const double v = value(x, slope);
    if (!(slope != 0)) return x;
    const double y = x - v / slope;
    if (!(y >= l && y <= l + w)) return x;
    double unused;
    return std::fabs(value(y, unused)) < std::fabs(v) ? y : x;
}

struct Event {
    double t;
    int slot;  // the interval's index in the ray's scratch lists
    bool enter;
};

// Per-thread scratch lists of one ray's intervals, kept between rays to avoid allocation.
struct Sweep {
    std::vector<Event> events;
    std::vector<int> element;          // per interval
    std::vector<std::array<double, 5>> quartic;  // per interval, made on entry
    std::vector<int> active, position; // the intervals the sweep is in, and where in `active`
    // seen[i] == ray: element i's interval is collected already (the windows overlap).
    std::vector<uint32_t> seen;
    uint32_t ray = 0;
};

// The gradient of the density at p from the elements of the active intervals.
glm::dvec3 active_gradient(const BlobShape& s, const Sweep& sw, const glm::dvec3& p);

// The elements whose boxes the ray o + t d crosses for t in [tmin, tmax], an element once
// per box of it (the caller skips repeats along a ray).
template <class F>
void for_each_candidate(const BlobShape& s, const glm::dvec3& o, const glm::dvec3& d,
                        double tmin, double tmax, const F& f) {
    s.tree.traverse(SlabRay(o, d), tmin, tmax,
                    [&](uint32_t i) { f(int(s.box_element[s.tree.order()[i]])); });
}

// The elements whose boxes hold the point p, each once.
template <class F> void for_each_element_at(const BlobShape& s, const glm::dvec3& p, const F& f) {
    if (!s.pieces) {
        for_each_candidate(s, p, glm::dvec3(0), -kHuge, 0, f);
        return;
    }
    thread_local std::vector<int> found;
    found.clear();
    for_each_candidate(s, p, glm::dvec3(0), -kHuge, 0, [&](int i) { found.push_back(i); });
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    for (int i : found) f(i);
}

// A cylinder longer than this many diameters is boxed piece by piece.
constexpr double kPieceDiameters = 1;
constexpr int kMostPieces = 64;

// The boxes of element e: one, or for a long cylinder one per piece of its axis.
void element_boxes(const BlobShape& s, const BlobElement& e, std::vector<Aabb>& out) {
    const double r = std::sqrt(e.rad2);
    const int first = e.kind == Kind::ApexCap ? 1 : 0;
    const int last = e.kind == Kind::Cylinder ? 1 : first;
    const int pieces =
        e.kind == Kind::Cylinder
            ? int(std::clamp(std::ceil(e.length / (2 * r * kPieceDiameters)), 1.0, double(kMostPieces)))
            : 1;
    for (int k = 0; k < pieces; ++k) {
        // Piece k spans [k, k + 1] / pieces of the axis (a sphere or cap: its one end).
        const double from = first * e.length + (last - first) * e.length * k / pieces;
        const double to = first * e.length + (last - first) * e.length * (k + 1) / pieces;
        Aabb box;
        for (const double at : {from, to}) {
            box.expand(e.centre + at * e.axis - glm::dvec3(r));
            box.expand(e.centre + at * e.axis + glm::dvec3(r));
        }
        out.push_back(e.transform < 0 ? box : transformed(box, s.to_component[e.transform]));
    }
}

void build_tree(BlobShape& s) {
    std::vector<Aabb> boxes;
    Aabb positive;
    for (size_t i = 0; i < s.elements.size(); ++i) {
        const size_t first = boxes.size();
        element_boxes(s, s.elements[i], boxes);
        s.box_element.resize(boxes.size(), uint32_t(i));
        if (s.elements[i].c[2] > 0)
            for (size_t k = first; k < boxes.size(); ++k) positive.expand(boxes[k]);
    }
    s.pieces = boxes.size() > s.elements.size();
    s.tree.build(boxes, kLeafSize);
    s.box = s.tree.bounds();
    s.bound = s.threshold > kInsideTolerance ? positive : s.box;
}

}  // namespace

BlobShape make_blob(const scene::Blob& b) {
    BlobShape s;
    s.threshold = b.threshold;
    s.sturm = b.sturm;
    s.valid = std::isfinite(b.threshold);
    for (size_t i = 0; i < b.components.size(); ++i) {
        const scene::Blob::Component& c = b.components[i];
        s.textures.push_back(c.texture.empty() ? nullptr : &c.texture);
        s.textured |= !c.texture.empty();
        if (c.radius == 0) continue;  // no density anywhere (POV-Ray draws nothing of it)
        if (!(c.radius > 0) || !std::isfinite(c.radius) || !std::isfinite(c.strength) ||
            !std::isfinite(glm::dot(c.a, c.a) + glm::dot(c.b, c.b))) {
            s.valid = false;
            continue;
        }
        BlobElement e;
        e.component = int(i);
        if (c.transform) {
            e.transform = int(s.to_component.size());
            s.to_component.push_back(*c.transform);
        }
        e.rad2 = c.radius * c.radius;
        e.c[0] = c.strength / (e.rad2 * e.rad2);
        e.c[1] = -2 * c.strength / e.rad2;
        e.c[2] = c.strength;
        e.centre = c.a;
        if (!c.cylinder) {
            s.elements.push_back(e);
            continue;
        }
        e.length = glm::length(c.b - c.a);
        if (!(e.length > 0)) {
            s.valid = false;
            continue;
        }
        e.axis = (c.b - c.a) / e.length;
        for (Kind k : {Kind::Cylinder, Kind::BaseCap, Kind::ApexCap}) {
            e.kind = k;
            s.elements.push_back(e);
        }
    }
    build_tree(s);
    return s;
}

double blob_element_density(const BlobShape& s, const BlobElement& e, const glm::dvec3& p) {
    glm::dvec3 v;
    if (!element_offset(e, to_element(s, e, p), v)) return 0;
    const double d2 = glm::dot(v, v);
    if (d2 >= e.rad2) return 0;
    return (e.c[0] * d2 + e.c[1]) * d2 + e.c[2];
}

double blob_density(const BlobShape& s, const glm::dvec3& p) {
    double sum = 0;
    for_each_element_at(s, p, [&](int i) { sum += blob_element_density(s, s.elements[i], p); });
    return sum;
}

namespace {

glm::dvec3 element_gradient(const BlobShape& s, const BlobElement& e, const glm::dvec3& p) {
    glm::dvec3 v;
    if (!element_offset(e, to_element(s, e, p), v)) return glm::dvec3(0);
    const double d2 = glm::dot(v, v);
    if (d2 >= e.rad2) return glm::dvec3(0);
    const glm::dvec3 local = (4 * e.c[0] * d2 + 2 * e.c[1]) * v;
    return e.transform < 0 ? local : s.to_component[e.transform].normal(local);
}

glm::dvec3 active_gradient(const BlobShape& s, const Sweep& sw, const glm::dvec3& p) {
    glm::dvec3 g(0);
    for (int slot : sw.active) g += element_gradient(s, s.elements[sw.element[slot]], p);
    return g;
}

}  // namespace

glm::dvec3 blob_gradient(const BlobShape& s, const glm::dvec3& p) {
    glm::dvec3 g(0);
    for_each_element_at(s, p, [&](int i) { g += element_gradient(s, s.elements[i], p); });
    return g;
}

bool inside(const BlobShape& s, const glm::dvec3& p) {
    return s.valid && blob_density(s, p) > s.threshold - kInsideTolerance;
}

namespace {

// The intervals of the elements whose boxes the unit ray o + t d crosses within [from, to]
// and that no earlier window collected, their events appended unsorted.
void collect_window(const BlobShape& s, const glm::dvec3& o, const glm::dvec3& d, double from,
                    double to, Sweep& sw) {
    for_each_candidate(s, o, d, from, to, [&](int i) {
        if (sw.seen[size_t(i)] == sw.ray) return;
        sw.seen[size_t(i)] = sw.ray;
        const BlobElement& e = s.elements[i];
        double t0, t1;
        if (!element_interval(e, to_element(s, e, o), to_element_dir(s, e, d), t0, t1)) return;
        if (t1 < kDepthBlob) return;
        t0 = std::max(t0, kDepthBlob);
        const int slot = int(sw.element.size());
        sw.element.push_back(i);
        sw.events.push_back({t0, slot, true});
        sw.events.push_back({t1, slot, false});
    });
}

// The first window's share of the ray's span through the blob's box; each next window is
// twice as long as the one before.
constexpr double kFirstWindow = 1.0 / 2;

}  // namespace

// POV-Ray collects every interval along the ray, sorts them and sweeps them front to back
// until a piece has a root. Here the intervals are collected window by window along the
// ray's span through the blob's box, so a ray that hits stops collecting soon after its
// hit: after a window ending at W every event before W is known (an element entered before
// W has a box the window crossed), so the sweep runs up to W. The sums are POV-Ray's; its
// scale (the last event, known only at the end) becomes the box's exit, which moves the
// roots by rounding only (each is polished on the unscaled quartic).
bool intersect(const BlobShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const double len = glm::length(r.d);
    if (!(len > 0) || !std::isfinite(len)) return false;
    const glm::dvec3 d = r.d / len;
    const glm::dvec3& o = r.o;
    const double far = tmax * len;
    double enter, exit;
    if (!SlabRay(o, d).hits(s.box, kDepthBlob, kHuge, enter, exit) || !(enter <= far)) return false;
    if (!std::isfinite(exit)) return false;

    thread_local Sweep sw;
    std::vector<Event>& events = sw.events;
    events.clear();
    sw.element.clear();
    sw.active.clear();
    if (sw.seen.size() < s.elements.size()) sw.seen.resize(s.elements.size(), sw.ray);
    if (++sw.ray == 0) {  // the stamps wrapped: start them over
        std::fill(sw.seen.begin(), sw.seen.end(), 0u);
        sw.ray = 1;
    }
    auto by_depth = [](const Event& a, const Event& b) { return a.t < b.t; };

    // The running sum of the active elements' quartics, lowest power first: each added on
    // entry and subtracted on exit, as POV-Ray sums them.
    double sum[5] = {-s.threshold, 0, 0, 0, 0};
    double start = 0, scale = 0;
    glm::dvec3 so(0), sd(0);
    bool started = false;
    size_t k = 0;  // the next event to sweep
    const double last_end = std::min(exit, far);
    double window = (exit - enter) * kFirstWindow, from = enter;
    for (;;) {
        const double to = std::min(from + window, last_end);
        const bool final = !(to < last_end);
        const size_t old = events.size();
        collect_window(s, o, d, from, final ? far : to, sw);
        if (events.size() > old) {
            // An event a hair before the part already swept (rounding): it starts there.
            const double swept = k > 0 ? events[k - 1].t : -kHuge;
            for (size_t i = old; i < events.size(); ++i) events[i].t = std::max(events[i].t, swept);
            std::sort(events.begin() + std::ptrdiff_t(k), events.end(), by_depth);
        }
        if (sw.quartic.size() < sw.element.size()) {
            sw.quartic.resize(sw.element.size());
            sw.position.resize(sw.element.size());
        }
        if (!started && !events.empty() && (final || events.front().t <= to)) {
            // Start at the first entry and scale so the box's span from there is [0, 1].
            start = events.front().t >= kSmallTolerance ? events.front().t : 0;
            scale = exit - start;
            if (!(scale > 0) || !std::isfinite(scale)) return false;
            so = o + start * d;
            sd = d * scale;
            started = true;
        }
        for (; started && k + 1 < events.size() && (final || events[k + 1].t <= to); ++k) {
            const Event& ev = events[k];
            std::array<double, 5>& q = sw.quartic[ev.slot];
            if (ev.enter) {
                const BlobElement& e = s.elements[sw.element[ev.slot]];
                element_quartic(e, to_element(s, e, so), to_element_dir(s, e, sd), q.data());
                for (int i = 0; i < 5; ++i) sum[i] += q[i];
                sw.position[ev.slot] = int(sw.active.size());
                sw.active.push_back(ev.slot);
            } else {
                for (int i = 0; i < 5; ++i) sum[i] -= q[i];
                const int at = sw.position[ev.slot];
                sw.active[at] = sw.active.back();
                sw.position[sw.active[at]] = at;
                sw.active.pop_back();
            }
            const double l = (ev.t - start) / scale, w = (events[k + 1].t - ev.t) / scale;
            if (!(w > 0)) continue;
            // The world depths of the piece, to skip what lies before tmin.
            if ((l + w) * scale + start <= tmin * len) continue;
            if ((l * scale + start) / len >= tmax) return false;
            if (!may_have_root(sum, l, w)) continue;
            const double high_first[5] = {sum[4], sum[3], sum[2], sum[1], sum[0]};
            double roots[4];
            const int n = solve_pov_polynomial(4, high_first, roots, s.sturm, kRootTolerance);
            double best = tmax;
            bool found = false;
            for (int i = 0; i < n; ++i) {
                if (!(roots[i] >= l && roots[i] <= l + w)) continue;
                const double depth = (polished(sum, roots[i], l, w) * scale + start) / len;
                if (depth > tmin && depth > kDepthBlob && depth < kMaxDistance && depth < best) {
                    best = depth;
                    found = true;
                }
            }
            if (!found) continue;
            h.t = best;
            h.normal = -active_gradient(s, sw, r.at(best));
            if (!(glm::dot(h.normal, h.normal) > 0) || !std::isfinite(glm::dot(h.normal, h.normal)))
                h.normal = -d;  // a point where the gradient vanishes: face the ray
            return true;
        }
        if (final) return false;
        from = to;
        window *= 2;
    }
}

}  // namespace lumen::render

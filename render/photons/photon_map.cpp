#include "render/photons/photon_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

namespace lumen::render {

namespace {

constexpr double kPi = std::numbers::pi;

// POV-Ray's flattening of the gather sphere towards the surface.
constexpr double kFlatten = 16.0;

}  // namespace

Photon make_photon(const glm::dvec3& position, const glm::dvec3& colour,
                   const glm::dvec3& towards_origin) {
    Photon p{};
    for (int i = 0; i < 3; ++i) p.position[i] = float(position[i]);
    const double top = std::max({colour.x, colour.y, colour.z});
    if (top > 1e-32) {
        int e = 0;
        const double m = std::frexp(top, &e);
        const double scale = 256.0 * m / top;
        for (int i = 0; i < 3; ++i)
            p.rgbe[i] = uint8_t(std::clamp(std::floor(std::max(0.0, colour[i]) * scale), 0.0, 255.0));
        p.rgbe[3] = uint8_t(e + 250);  // wraps at 32 and above, as POV-Ray's byte does
    }
    const glm::dvec3 d = towards_origin;
    const double theta = std::asin(std::clamp(d.y, -1.0, 1.0));
    const double phi = std::atan2(d.z, d.x);
    p.theta = int8_t(std::trunc(theta * 127 / kPi));
    p.phi = int8_t(std::trunc(phi * 127 / kPi));
    return p;
}

glm::dvec3 Photon::colour() const {
    if (rgbe[3] == 0 && rgbe[0] == 0 && rgbe[1] == 0 && rgbe[2] == 0) return glm::dvec3(0);
    const double f = std::ldexp(1.0, int(rgbe[3]) - 258);
    return glm::dvec3(rgbe[0] * f, rgbe[1] * f, rgbe[2] * f);
}

glm::dvec3 Photon::direction() const {
    // The cosine and sine of each of the 256 angles a byte holds, computed once (a media
    // gather decodes a hundred directions per sample).
    struct Angles {
        double cos[256], sin[256];
        Angles() {
            for (int i = 0; i < 256; ++i) {
                const double a = (i - 128) * kPi / 127;
                cos[i] = std::cos(a);
                sin[i] = std::sin(a);
            }
        }
    };
    static const Angles angles;
    const int t = theta + 128, p = phi + 128;
    return {angles.cos[t] * angles.cos[p], angles.sin[t], angles.cos[t] * angles.sin[p]};
}

void PhotonMap::build() {
    if (!photons_.empty()) subdivide(0, int(photons_.size()) - 1);
    bound_ranges();
}

void PhotonMap::bound_ranges() {
    bounds_.clear();
    if (!photons_.empty()) bound_range(0, int(photons_.size()) - 1, 1);
}

PhotonMap::Bounds PhotonMap::bound_range(int start, int end, size_t node) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    Bounds b{{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
    auto take = [&b](const Bounds& o) {
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = std::min(b.lo[a], o.lo[a]);
            b.hi[a] = std::max(b.hi[a], o.hi[a]);
        }
    };
    if (end - start + 1 < kBoundedRange) {
        for (int i = start; i <= end; ++i) {
            const float* q = photons_[i].position;
            take({{q[0], q[1], q[2]}, {q[0], q[1], q[2]}});
        }
        return b;
    }
    const int mid = (start + end) >> 1;
    const float* q = photons_[mid].position;
    take({{q[0], q[1], q[2]}, {q[0], q[1], q[2]}});
    take(bound_range(start, mid - 1, 2 * node));
    take(bound_range(mid + 1, end, 2 * node + 1));
    if (bounds_.size() <= node) bounds_.resize(node + 1);
    bounds_[node] = b;
    return b;
}

// [start, end] inclusive, split at mid = (start + end) / 2 on the widest axis. A range of two
// is left as it is (POV-Ray's quirk: its second photon may lie on the wrong side).
void PhotonMap::subdivide(int start, int end) {
    while (start <= end) {
        if (start == end) {
            photons_[start].axis = 0;
            return;
        }
        float lo[3], hi[3];
        for (int a = 0; a < 3; ++a) lo[a] = hi[a] = photons_[start].position[a];
        for (int i = start + 1; i <= end; ++i)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], photons_[i].position[a]);
                hi[a] = std::max(hi[a], photons_[i].position[a]);
            }
        int axis = 0;
        if (hi[1] - lo[1] > hi[axis] - lo[axis]) axis = 1;
        if (hi[2] - lo[2] > hi[axis] - lo[axis]) axis = 2;
        const int mid = (start + end) >> 1;
        if (end - start > 1)
            std::nth_element(photons_.begin() + start, photons_.begin() + mid,
                             photons_.begin() + end + 1, [axis](const Photon& a, const Photon& b) {
                                 return a.position[axis] < b.position[axis];
                             });
        photons_[mid].axis = uint8_t(axis);
        subdivide(start, mid - 1);
        start = mid + 1;  // the right half without recursing
    }
}

namespace {

// The nearest-photon search of one gather: the kd-tree walked depth first, the side of each
// split that holds p first, and the other side afterwards if its split plane is then within
// reach (POV-Ray's order, which decides the result once the heap is full). Deferred sides
// wait on a stack rather than in recursive calls, and the kept photons form a max-heap on the
// distance in two parallel arrays.
struct Gather {
    const Photon* photons;
    const std::vector<PhotonMap::Bounds>& bounds;
    glm::dvec3 p, n;
    bool flatten;
    int max;
    double dmax;
    double* keys;
    const Photon** items;
    int count = 0;

    void add(const Photon* ph, double d) {
        if (count < max) {  // sift up from the new last place
            int i = count++;
            while (i > 0) {
                const int parent = (i - 1) / 2;
                if (keys[parent] >= d) break;
                keys[i] = keys[parent];
                items[i] = items[parent];
                i = parent;
            }
            keys[i] = d;
            items[i] = ph;
            return;
        }
        // Full: the farthest kept photon makes way, and the reach shrinks to the new farthest.
        // The first time, the candidate was only compared with the start radius (POV-Ray's
        // quirk), so it may be farther than the photon it replaces.
        int i = 0;
        for (;;) {
            const int l = 2 * i + 1, r = l + 1;
            int big = i;
            double big_key = d;
            if (l < count && keys[l] > big_key) big = l, big_key = keys[l];
            if (r < count && keys[r] > big_key) big = r, big_key = keys[r];
            if (big == i) break;
            keys[i] = keys[big];
            items[i] = items[big];
            i = big;
        }
        keys[i] = d;
        items[i] = ph;
        dmax = keys[0];
    }

    // Whether a photon in the box could be kept: its squared distance from p, the least a
    // photon's (flattened or not) can be, is under dmax. A margin far above rounding keeps
    // every range that could hold a kept photon, so the gather is the same with or without it.
    bool within_reach(const PhotonMap::Bounds& b) const {
        double d = 0;
        for (int a = 0; a < 3; ++a) {
            const double below = double(b.lo[a]) - p[a], above = p[a] - double(b.hi[a]);
            const double gap = std::max({below, above, 0.0});
            d += gap * gap;
        }
        return !(d > dmax * (1 + 1e-9));
    }

    void run(int size) {
        struct Deferred {
            int start, end;
            size_t node;  // the range's number (PhotonMap::Bounds)
            double sq;    // the squared distance from p to the split plane
        };
        Deferred stack[64];  // one per level of the tree at most
        int top = 0;
        int start = 0, end = size - 1;
        size_t node = 1;
        for (;;) {
            while (start <= end) {
                // A range whose box is out of reach holds no photon to keep (a gather above
                // a floor of photons would otherwise walk every range near it in x and z).
                if (end - start + 1 >= PhotonMap::kBoundedRange && node < bounds.size() &&
                    !within_reach(bounds[node]))
                    break;
                const int mid = (start + end) >> 1;
                const Photon& ph = photons[mid];
                const double vx = ph.position[0] - p.x, vy = ph.position[1] - p.y,
                             vz = ph.position[2] - p.z;
                double d = vx * vx + vy * vy + vz * vz;
                // Flattening only lengthens the distance, so a photon out of reach stays out.
                if (d < dmax) {
                    if (flatten) d *= 1 + kFlatten * std::fabs(n.x * vx + n.y * vy + n.z * vz);
                    if (d < dmax) add(&ph, d);
                }
                const double delta = p[ph.axis] - ph.position[ph.axis];
                // Chosen without branches: which side p lies on is a coin toss per node.
                const bool below = delta < 0;
                const int far_start = below ? mid + 1 : start, far_end = below ? end : mid - 1;
                stack[top] = {far_start, far_end, below ? 2 * node + 1 : 2 * node, delta * delta};
                top += far_start <= far_end;
                start = below ? start : mid + 1;
                end = below ? mid - 1 : end;
                node = below ? 2 * node : 2 * node + 1;
            }
            do {
                if (top == 0) return;
                --top;
            } while (!(stack[top].sq < dmax));
            start = stack[top].start;
            end = stack[top].end;
            node = stack[top].node;
        }
    }
};

}  // namespace

void PhotonMap::gather(const glm::dvec3& p, const glm::dvec3& normal, double radius, int max,
                       GatheredPhotons& out) const {
    out.photons.resize(std::max(max, 0));
    out.distances.resize(out.photons.size());
    Gather g{photons_.data(), bounds_, p, normal, normal != glm::dvec3(0), max, radius * radius,
             out.distances.data(), out.photons.data()};
    if (max > 0 && !photons_.empty()) g.run(int(photons_.size()));
    out.photons.resize(g.count);
    out.distances.resize(g.count);
    out.radius_sq = g.dmax;
}

void PhotonMap::gather_adaptive(const glm::dvec3& p, const glm::dvec3& normal,
                                const GatherSettings& s, GatheredPhotons& out) const {
    gather(p, normal, s.radius, s.max, out);
    if (out.count() >= s.min) return;
    const double density = out.count() > 0 ? out.count() / out.radius_sq : 1e-16;
    thread_local GatheredPhotons wider;
    gather(p, normal, 3 * s.radius, s.max, wider);
    const double wider_density = wider.count() / wider.radius_sq;
    if ((wider_density - density) / density < s.expand_percent ||
        (wider.count() > 0 && wider.count() < s.expand_min))
        std::swap(out, wider);
}

double PhotonMap::choose_radius(int gather_max, double multiplier, bool volume) const {
    if (photons_.empty() || gather_max <= 0) return 0;
    const int samples = int(std::clamp<size_t>(photons_.size() / 20, 100, 1000));
    std::minstd_rand rng(1);
    auto pick = [&]() -> const Photon& {
        return photons_[std::uniform_int_distribution<size_t>(0, photons_.size() - 1)(rng)];
    };
    auto at = [](const Photon& ph) {
        return glm::dvec3(ph.position[0], ph.position[1], ph.position[2]);
    };
    const auto density = [volume](const GatheredPhotons& g) {
        return volume ? 3 * g.count() / (4 * kPi * g.radius_sq * std::sqrt(g.radius_sq))
                      : g.count() / (kPi * g.radius_sq);
    };
    GatheredPhotons g;
    double mean = 0;
    for (int i = 0; i < samples; ++i) {
        gather(at(pick()), glm::dvec3(0), 1e7, gather_max, g);
        mean += density(g);
    }
    mean /= samples;
    if (!(mean > 0)) return 0;
    double radius = volume ? std::pow(3 * gather_max / (4 * kPi * mean), 0.3333)
                           : std::sqrt(gather_max / (kPi * mean));
    int typical = 0;
    for (int i = 0; i < samples; ++i) {
        gather(at(pick()), glm::dvec3(0), radius, gather_max, g);
        const double d = density(g);
        if (d > 0.05 * mean && d < 0.7 * mean) ++typical;
    }
    radius *= (1 + 20.0 * typical / samples) * multiplier;
    return volume ? 2 * radius : radius;
}

}  // namespace lumen::render

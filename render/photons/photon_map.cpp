#include "render/photons/photon_map.hpp"

#include <algorithm>
#include <cmath>
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

struct Gather {
    const std::vector<Photon>& photons;
    glm::dvec3 p, n;
    bool flatten;
    int max;
    double dmax;
    GatheredPhotons& out;

    void add(const Photon* ph, double d) {
        auto& keys = out.distances;
        auto& items = out.photons;
        // A max-heap on the distance, kept in the two parallel arrays.
        auto sift_up = [&](size_t i) {
            while (i > 0) {
                const size_t parent = (i - 1) / 2;
                if (keys[parent] >= keys[i]) break;
                std::swap(keys[parent], keys[i]);
                std::swap(items[parent], items[i]);
                i = parent;
            }
        };
        if (int(items.size()) < max) {
            keys.push_back(d);
            items.push_back(ph);
            sift_up(items.size() - 1);
            return;
        }
        // Full: the farthest kept photon makes way, and the reach shrinks to the new farthest.
        // The first time, the candidate was only compared with the start radius (POV-Ray's
        // quirk), so it may be farther than the photon it replaces.
        keys[0] = d;
        items[0] = ph;
        size_t i = 0;
        for (;;) {
            const size_t l = 2 * i + 1, r = l + 1;
            size_t big = i;
            if (l < keys.size() && keys[l] > keys[big]) big = l;
            if (r < keys.size() && keys[r] > keys[big]) big = r;
            if (big == i) break;
            std::swap(keys[big], keys[i]);
            std::swap(items[big], items[i]);
            i = big;
        }
        dmax = keys[0];
    }

    void visit(int start, int end) {
        while (start <= end) {
            const int mid = (start + end) >> 1;
            const Photon& ph = photons[mid];
            const glm::dvec3 v(ph.position[0] - p.x, ph.position[1] - p.y, ph.position[2] - p.z);
            double d = glm::dot(v, v);
            if (flatten) d *= 1 + kFlatten * std::fabs(glm::dot(n, v));
            if (d < dmax) add(&ph, d);
            const int axis = ph.axis;
            const double delta = p[axis] - ph.position[axis];
            const double sq = delta * delta;
            // The side p lies on first; the other only if the split plane is within reach.
            if (delta < 0) {
                if (mid - 1 >= start) visit(start, mid - 1);
                if (!(sq < dmax)) return;
                start = mid + 1;
            } else {
                if (end >= mid + 1) visit(mid + 1, end);
                if (!(sq < dmax)) return;
                end = mid - 1;
            }
        }
    }
};

}  // namespace

void PhotonMap::gather(const glm::dvec3& p, const glm::dvec3& normal, double radius, int max,
                       GatheredPhotons& out) const {
    out.photons.clear();
    out.distances.clear();
    Gather g{photons_, p, normal, normal != glm::dvec3(0), max, radius * radius, out};
    if (max > 0 && !photons_.empty()) g.visit(0, int(photons_.size()) - 1);
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

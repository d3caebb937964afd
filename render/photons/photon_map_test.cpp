// The photon map: POV-Ray's compact photon record, the kd-tree gather against a brute-force
// search (with POV's one known quirk), the flattened gather and the adaptive radius.
#include "render/photons/photon_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

namespace lumen::render {
namespace {

TEST(Photon, ColourPackedAsRgbe) {
    // POV-Ray's packing loses a little: 1e-4 comes back as 9.966e-5.
    const Photon p = make_photon(glm::dvec3(0), glm::dvec3(1e-4), glm::dvec3(0, 1, 0));
    EXPECT_NEAR(p.colour().x, 9.966e-5, 1e-8);
    const glm::dvec3 c(0.5, 0.25, 0.1);
    const glm::dvec3 back = make_photon(glm::dvec3(0), c, glm::dvec3(0, 1, 0)).colour();
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(back[i], c[i]);                  // the mantissas are truncated
        EXPECT_GT(back[i], c[i] - 0.5 / 128);  // by less than a step: at most max/128
    }
    EXPECT_EQ(make_photon(glm::dvec3(0), glm::dvec3(0), glm::dvec3(0, 1, 0)).colour(), glm::dvec3(0));
}

TEST(Photon, DirectionInTwoBytes) {
    std::mt19937 rng(3);
    std::normal_distribution<double> n;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
        const glm::dvec3 back = make_photon(glm::dvec3(0), glm::dvec3(1), d).direction();
        EXPECT_NEAR(glm::length(back), 1.0, 1e-12);
        // Steps of π/127 in each angle: within two steps of the true direction.
        EXPECT_GT(glm::dot(back, d), std::cos(2 * 3.14159265 / 127 * 1.5));
    }
}

std::vector<glm::dvec3> random_points(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<glm::dvec3> out;
    for (int i = 0; i < n; ++i) out.push_back({u(rng), u(rng), u(rng)});
    return out;
}

PhotonMap map_of(const std::vector<glm::dvec3>& points) {
    PhotonMap m;
    for (const auto& p : points) m.add(make_photon(p, glm::dvec3(1), glm::dvec3(0, 1, 0)));
    m.build();
    return m;
}

glm::dvec3 at(const Photon& p) { return {p.position[0], p.position[1], p.position[2]}; }

TEST(PhotonMap, GatherWithinRadiusFindsThePhotonsThere) {
    const auto points = random_points(3000, 1);
    const PhotonMap map = map_of(points);
    GatheredPhotons g;
    int found = 0, there = 0;
    for (const glm::dvec3& q : random_points(50, 2)) {
        map.gather(q, glm::dvec3(0), 0.15, 100000, g);
        int expected = 0;
        for (const Photon& p : map.photons())
            if (glm::dot(at(p) - q, at(p) - q) < 0.15 * 0.15) ++expected;
        for (const Photon* p : g.photons) EXPECT_LT(glm::dot(at(*p) - q, at(*p) - q), 0.15 * 0.15);
        EXPECT_LE(g.count(), expected);
        EXPECT_DOUBLE_EQ(g.radius_sq, 0.15 * 0.15);  // the heap never filled
        found += g.count(), there += expected;
    }
    // POV-Ray leaves ranges of two photons unsorted in its tree, which hides a few from the
    // search (here about 3%); lumen keeps the quirk.
    EXPECT_GT(found, 0.9 * there);
    EXPECT_LT(found, there);
}

TEST(PhotonMap, FullGatherKeepsTheNearestButOne) {
    const auto points = random_points(5000, 4);
    const PhotonMap map = map_of(points);
    GatheredPhotons g;
    for (const glm::dvec3& q : random_points(40, 5)) {
        map.gather(q, glm::dvec3(0), 10.0, 50, g);
        ASSERT_EQ(g.count(), 50);
        std::vector<double> all;
        for (const Photon& p : map.photons()) all.push_back(glm::dot(at(p) - q, at(p) - q));
        std::sort(all.begin(), all.end());
        // POV-Ray's first replacement compares with the start radius, not the farthest kept,
        // so one kept photon may be farther than the 50th nearest; the rest are the nearest.
        int beyond = 0;
        double farthest = 0;
        for (const Photon* p : g.photons) {
            const double d = glm::dot(at(*p) - q, at(*p) - q);
            farthest = std::max(farthest, d);
            if (d > all[49] * (1 + 1e-12)) ++beyond;
        }
        EXPECT_LE(beyond, 1);
        EXPECT_NEAR(g.radius_sq, farthest, 1e-12);
    }
}

TEST(PhotonMap, GatherIsFlattenedTowardsTheSurface) {
    // Two photons 0.1 from the point: one in the surface's plane, one along its normal. The
    // normal one counts 1 + 16·0.1 times farther (POV's ellipsoid).
    PhotonMap map;
    map.add(make_photon({0.1, 0, 0}, glm::dvec3(1), glm::dvec3(0, 1, 0)));
    map.add(make_photon({0, 0.1, 0}, glm::dvec3(1), glm::dvec3(0, 1, 0)));
    map.build();
    GatheredPhotons g;
    map.gather(glm::dvec3(0), glm::dvec3(0, 1, 0), 0.12, 10, g);
    ASSERT_EQ(g.count(), 1);
    EXPECT_NEAR(g.photons[0]->position[0], 0.1, 1e-6);
    map.gather(glm::dvec3(0), glm::dvec3(0), 0.12, 10, g);  // no normal: a sphere
    EXPECT_EQ(g.count(), 2);
}

TEST(PhotonMap, AdaptiveGatherWidensWhereTooFewWereFound) {
    const PhotonMap map = map_of(random_points(20000, 6));
    GatherSettings s;
    s.min = 20;
    s.max = 100;
    s.radius = 0.05;  // finds about 1 photon: the wider gather (three times the radius) wins
    GatheredPhotons g;
    map.gather_adaptive(glm::dvec3(0), glm::dvec3(0), s, g);
    EXPECT_GT(g.count(), 5);
    EXPECT_NEAR(g.radius_sq, 0.15 * 0.15, 1e-12);
    s.radius = 0.3;  // enough already: one gather
    map.gather_adaptive(glm::dvec3(0), glm::dvec3(0), s, g);
    EXPECT_GE(g.count(), 20);
}

// POV-Ray's gather as it describes it, recursively: the photon at the middle of the range,
// the half p lies in, then the other half if its split plane is still within reach; a photon
// joins a max-heap of at most `max` when nearer than the reach, which shrinks to the heap's
// farthest once a photon has replaced one. The result depends on this order once the heap
// fills, so lumen's gather must visit in it.
struct ReferenceGather {
    const std::vector<Photon>& photons;
    glm::dvec3 p, n;
    int max;
    double reach;
    std::vector<double> keys;
    std::vector<const Photon*> items;

    void add(const Photon* ph, double d) {
        if (int(keys.size()) < max) {
            keys.push_back(d), items.push_back(ph);
            for (size_t i = keys.size() - 1; i > 0 && keys[(i - 1) / 2] < keys[i]; i = (i - 1) / 2)
                std::swap(keys[i], keys[(i - 1) / 2]), std::swap(items[i], items[(i - 1) / 2]);
            return;
        }
        keys[0] = d, items[0] = ph;
        for (size_t i = 0;;) {
            size_t big = i;
            for (size_t c : {2 * i + 1, 2 * i + 2})
                if (c < keys.size() && keys[c] > keys[big]) big = c;
            if (big == i) break;
            std::swap(keys[i], keys[big]), std::swap(items[i], items[big]);
            i = big;
        }
        reach = keys[0];
    }
    void visit(int start, int end) {
        if (start > end) return;
        const int mid = (start + end) / 2;
        const Photon& ph = photons[mid];
        const glm::dvec3 v = at(ph) - p;
        double d = glm::dot(v, v);
        if (n != glm::dvec3(0)) d *= 1 + 16 * std::fabs(glm::dot(n, v));
        if (d < reach) add(&ph, d);
        const double delta = p[ph.axis] - ph.position[ph.axis];
        const bool below = delta < 0;
        visit(below ? start : mid + 1, below ? mid - 1 : end);
        if (delta * delta < reach) visit(below ? mid + 1 : start, below ? end : mid - 1);
    }
};

TEST(PhotonMap, GatherVisitsInPovRaysOrder) {
    // Photons on a wavy sheet and in a cloud; gathers with and without a normal, some filling
    // the heap (max 30) and some not: the same photons in the same heap order, the same reach.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<glm::dvec3> points = random_points(2000, 12);
    for (int i = 0; i < 6000; ++i) {
        const double x = u(rng), z = u(rng);
        points.push_back({x, 0.1 * std::sin(5 * x) * std::cos(3 * z), z});
    }
    const PhotonMap map = map_of(points);
    GatheredPhotons g;
    int full = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::dvec3 q(u(rng), 0.2 * u(rng), u(rng));
        const glm::dvec3 n = i % 2 ? glm::normalize(glm::dvec3(0.1 * u(rng), 1, 0.1 * u(rng)))
                                   : glm::dvec3(0);
        const double radius = 0.02 + 0.2 * (u(rng) + 1);
        ReferenceGather ref{map.photons(), q, n, 30, radius * radius, {}, {}};
        ref.visit(0, int(map.size()) - 1);
        map.gather(q, n, radius, 30, g);
        ASSERT_EQ(g.photons, ref.items);
        ASSERT_EQ(g.distances, ref.keys);
        ASSERT_EQ(g.radius_sq, ref.reach);
        full += g.count() == 30;
    }
    EXPECT_GT(full, 100);
    EXPECT_LT(full, 300);
}

TEST(PhotonMap, AutomaticRadiusGathersAboutMaxPhotons) {
    // A uniform layer of photons: the chosen radius should hold roughly gather Max of them
    // (POV-Ray's estimate, widened where densities vary).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    PhotonMap map;
    for (int i = 0; i < 20000; ++i)
        map.add(make_photon({u(rng), 0, u(rng)}, glm::dvec3(1), glm::dvec3(0, 1, 0)));
    map.build();
    const double r = map.choose_radius(100, 1.0);
    const double expected = std::sqrt(100 / (3.14159265 * 20000 / 4.0));
    EXPECT_GT(r, expected);
    EXPECT_LT(r, 25 * expected);
    EXPECT_EQ(r, map.choose_radius(100, 1.0));  // deterministic
    EXPECT_NEAR(map.choose_radius(100, 2.0), 2 * r, 1e-12);
}

}  // namespace
}  // namespace lumen::render

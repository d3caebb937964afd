#include "render/focal_blur.hpp"

#include <cmath>
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace lumen::render {
namespace {

scene::Camera blurred_camera(int max, int min = 0, double aperture = 1, double focal = 10) {
    scene::Camera c;
    c.location = {0, 0, -5};
    c.blur = scene::Camera::FocalBlur{};
    c.blur->aperture = aperture;
    c.blur->min_samples = min;
    c.blur->max_samples = max;
    c.blur->focal_distance = focal;
    return c;
}

TEST(FocalBlur, ChiSquareQuantilesMatchTheTables) {
    // Upper-tail quantiles from the standard tables (p = 0.9 and 0.1, i.e. the 10% and 90%
    // points of the distribution).
    EXPECT_NEAR(chi_square_upper_quantile(1, 0.9), 0.01579, 1e-5);
    EXPECT_NEAR(chi_square_upper_quantile(2, 0.9), 0.2107, 1e-4);
    EXPECT_NEAR(chi_square_upper_quantile(10, 0.9), 4.865, 1e-3);
    EXPECT_NEAR(chi_square_upper_quantile(10, 0.1), 15.987, 1e-3);
    EXPECT_NEAR(chi_square_upper_quantile(100, 0.1), 118.498, 1e-2);
    EXPECT_TRUE(std::isfinite(chi_square_upper_quantile(5000, 0.9)));
}

TEST(FocalBlur, GridsThenDistinctHaltonPointsInsideTheAperture) {
    for (int max : {1, 4, 5, 7, 19, 20, 37, 120, 1000}) {
        const FocalBlur blur(blurred_camera(max));
        EXPECT_EQ(blur.max_samples(), max);
        std::set<std::pair<double, double>> seen;
        for (int n = 0; n < max; ++n) {
            const glm::dvec2 p = blur.aperture_point(n);
            EXPECT_LE(glm::length(p), 0.5 + 1e-6) << max << " " << n;
            EXPECT_TRUE(seen.insert({p.x, p.y}).second) << "repeated point " << n << " of " << max;
        }
        EXPECT_TRUE(blur.batch_ends(max - 1));  // the last sample always ends a batch
    }
    const FocalBlur hex(blurred_camera(37));
    EXPECT_EQ(hex.aperture_point(0), glm::dvec2(0, 0));  // HexGrid4 starts at the centre
    // Batches of 7, 6, 6, 4, 4, 4, 4, 2 for the 37-point grid.
    for (int n = 0; n < 37; ++n) {
        const bool end = n == 6 || n == 12 || n == 18 || n == 22 || n == 26 || n == 30 ||
                         n == 34 || n == 36;
        EXPECT_EQ(hex.batch_ends(n), end) << n;
    }
}

TEST(FocalBlur, RaysMeetOnTheFocalPlane) {
    const scene::Camera c = blurred_camera(37, 0, 2, 10);
    const CameraModel model(c, 640, 480);
    const FocalBlur blur(c);
    // Every aperture ray of one pixel passes (almost) through the same focal-plane point:
    // their sub-pixel offsets differ by under a pixel, so the spread there is small against
    // the aperture's size at the lens.
    glm::dvec3 first{};
    double spread = 0, lens = 0;
    for (int n = 0; n < 37; ++n) {
        const std::optional<Ray> r = blur.ray(model, 200, 300, n);
        ASSERT_TRUE(r);
        EXPECT_NEAR(glm::length(r->dir), 1, 1e-12);
        const double t = (10 - (r->origin.z - c.location.z)) / r->dir.z;
        const glm::dvec3 p = r->origin + t * r->dir;
        if (n == 0) first = p;
        spread = std::max(spread, glm::length(p - first));
        lens = std::max(lens, glm::length(r->origin - c.location));
        EXPECT_LE(glm::length(r->origin - c.location), 1.0 + 1e-9);  // within the aperture
    }
    EXPECT_GT(lens, 0.4);
    EXPECT_LT(spread, 0.1 * lens);
}

TEST(FocalBlur, ZeroVarianceStopsAfterTheFirstBatchUnlessAMinimumIsAsked) {
    const FocalBlur blur(blurred_camera(37));
    const double s1[4] = {7, 7, 7, 0}, s2[4] = {7, 7, 7, 0};
    EXPECT_TRUE(blur.settled(7, s1, s2));
    const double noisy1[4] = {3.5, 0, 0, 0}, noisy2[4] = {3.5, 0, 0, 0};
    EXPECT_FALSE(blur.settled(7, noisy1, noisy2));
    const FocalBlur at_least(blurred_camera(37, 13));
    EXPECT_FALSE(at_least.settled(7, s1, s2));
    const double s13[4] = {13, 13, 13, 0}, q13[4] = {13, 13, 13, 0};
    EXPECT_TRUE(at_least.settled(13, s13, q13));
}

TEST(FocalBlur, NoNaNAtTheImageEdgesOrWithDegenerateSettings) {
    for (double focal : {1e-9, 1.0, 1e9})
        for (double aperture : {-1.0, 1e-12, 1e6}) {
            const scene::Camera c = blurred_camera(20, 0, aperture, focal);
            const CameraModel model(c, 8, 8);
            const FocalBlur blur(c);
            for (int n = 0; n < 20; ++n)
                for (double x : {-0.5, 0.0, 7.5})
                    if (const std::optional<Ray> r = blur.ray(model, x, x, n)) {
                        EXPECT_TRUE(std::isfinite(r->dir.x + r->dir.y + r->dir.z));
                        EXPECT_TRUE(std::isfinite(r->origin.x + r->origin.y + r->origin.z));
                    }
        }
}

}  // namespace
}  // namespace lumen::render

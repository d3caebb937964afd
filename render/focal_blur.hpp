// POV-Ray 3.7's focal blur: each sample averages rays that leave points of the aperture disc
// and meet where the unblurred ray crosses the focal plane. The aperture points (a hexagonal
// grid of 7, 19 or 37, then more from a Halton sequence), their per-pixel jitter and the
// variance test that stops a sample early are POV's, so the noise pattern is deterministic
// and close to POV-Ray's.
#pragma once
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/camera.hpp"
#include "render/ray.hpp"
#include "scene/camera.hpp"

namespace lumen::render {

// The inverse of the chi-square distribution's upper tail: the x at which the probability
// of a value above x with `df` degrees of freedom is `p` (Cephes' chdtri).
double chi_square_upper_quantile(double df, double p);

class FocalBlur {
public:
    // `camera` must have focal blur (camera.blur).
    explicit FocalBlur(const scene::Camera& camera);

    int max_samples() const { return max_; }
    int min_samples() const { return min_; }
    // Whether a batch of samples ends after sample n (0-based): the variance is tested there.
    bool batch_ends(int n) const { return n + 1 == max_ || batch_end_[size_t(n)]; }
    // Whether the mean of n samples with sums s1 and squared sums s2 (r, g, b, t) is
    // settled: each channel's variance of the mean below the threshold for n samples. Only
    // counts that end a batch (batch_ends(n - 1)) have a threshold; others never settle.
    bool settled(int n, const double s1[4], const double s2[4]) const;
    // Ray n of the sample at image position (x, y) (CameraModel's coordinates); none where
    // the projection has none there.
    std::optional<Ray> ray(const CameraModel& camera, double x, double y, int n) const;

    // The aperture point of ray n before its jitter, in units of the aperture's diameter.
    glm::dvec2 aperture_point(int n) const { return points_[size_t(n)]; }

private:
    int min_ = 0, max_ = 1;
    std::vector<glm::dvec2> points_;
    std::vector<unsigned char> batch_end_;
    std::vector<double> threshold_;  // by sample count - 1
    double jitter_scale_ = 0;        // 2 * the aperture jitter's size, in units of the diameter
    double radius_ = 0;              // aperture / 2
    double focal_scale_ = 1;         // focal distance / |direction|
    double direction_length_ = 1;
    glm::dvec3 location_, x_axis_, y_axis_, view_;
};

}  // namespace lumen::render

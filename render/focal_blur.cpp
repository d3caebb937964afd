#include "render/focal_blur.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/jitter.hpp"

namespace lumen::render {
namespace {

// POV-Ray's aperture grids, in units of the aperture's diameter, in the order it traces them.
constexpr double kGrid1[][2] = {{-0.25, 0.25}, {0.25, 0.25}, {-0.25, -0.25}, {0.25, -0.25}};
constexpr double kHexGrid2[][2] = {{-0.288675, 0},         {0, 0},
                                   {0.288675, 0},          {-0.144338, 0.25},
                                   {-0.144338, -0.25},     {0.144338, 0.25},
                                   {0.144338, -0.25}};
constexpr double kHexGrid3[][2] = {
    {-0.19245, 0.333333},  {-0.19245, -0.333333}, {0.19245, 0.333333},   {0.19245, -0.333333},
    {0.3849, 0},           {-0.3849, 0},          {0, 0},                {0, 0.333333},
    {0, -0.333333},        {-0.288675, 0.166667}, {-0.288675, -0.166667}, {0.288675, 0.166667},
    {0.288675, -0.166667}, {-0.096225, 0.166667}, {-0.096225, -0.166667}, {0.096225, 0.166667},
    {0.096225, -0.166667}, {-0.19245, 0},         {0.19245, 0}};
constexpr double kHexGrid4[][2] = {
    {0, 0},                {-0.216506, 0.375},    {0.216506, -0.375},    {-0.216506, -0.375},
    {0.216506, 0.375},     {-0.433013, 0},        {0.433013, 0},         {-0.144338, 0.25},
    {0.144338, -0.25},     {-0.144338, -0.25},    {0.144338, 0.25},      {-0.288675, 0},
    {0.288675, 0},         {-0.072169, 0.125},    {0.072169, -0.125},    {-0.072169, -0.125},
    {0.072169, 0.125},     {-0.144338, 0},        {0.144338, 0},         {-0.360844, 0.125},
    {-0.360844, -0.125},   {0.360844, 0.125},     {0.360844, -0.125},    {-0.288675, 0.25},
    {-0.288675, -0.25},    {0.288675, 0.25},      {0.288675, -0.25},     {-0.072169, 0.375},
    {-0.072169, -0.375},   {0.072169, 0.375},     {0.072169, -0.375},    {-0.216506, 0.125},
    {-0.216506, -0.125},   {0.216506, 0.125},     {0.216506, -0.125},    {0, 0.25},
    {0, -0.25}};

struct Grid {
    const double (*points)[2];
    int size;
    std::vector<int> batches;  // then 4 per batch
    double jitter;             // the jitter's size when exactly this many samples are asked (0: none)
};

Grid grid_for(int max) {
    if (max >= 37) return {kHexGrid4, 37, {7, 6, 6, 4, 4, 4, 4, 2}, 0.0721688};
    if (max >= 19) return {kHexGrid3, 19, {7, 6, 6}, 0.096225};
    if (max >= 7) return {kHexGrid2, 7, {7}, 0.144338};
    return {kGrid1, 4, {}, 0};
}

double halton(int index, int base) {
    double f = 1, r = 0;
    for (int i = index; i > 0; i /= base) {
        f /= base;
        r += f * (i % base);
    }
    return r;
}

// The regularised upper incomplete gamma function Q(a, x) (series below a + 1, continued
// fraction above).
double upper_gamma(double a, double x) {
    if (x <= 0) return 1;
    const double log_front = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        double term = 1 / a, sum = term;
        for (int n = 1; n < 1000 && std::fabs(term) > 1e-16 * std::fabs(sum); ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return std::clamp(1 - sum * std::exp(log_front), 0.0, 1.0);
    }
    // Lentz's method for the continued fraction of Q.
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1) < 1e-16) break;
    }
    return std::clamp(std::exp(log_front) * h, 0.0, 1.0);
}

}  // namespace

double chi_square_upper_quantile(double df, double p) {
    if (!(df > 0) || !(p > 0) || !(p < 1)) return p >= 1 ? 0 : HUGE_VAL;
    // Q(df/2, x/2) falls from 1 to 0 as x grows: bisect on it.
    double lo = 0, hi = std::max(1.0, df);
    while (upper_gamma(df / 2, hi / 2) > p && hi < 1e12) hi *= 2;
    for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
        const double mid = (lo + hi) / 2;
        (upper_gamma(df / 2, mid / 2) > p ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

FocalBlur::FocalBlur(const scene::Camera& camera) {
    const scene::Camera::FocalBlur& b = *camera.blur;
    max_ = std::max(1, b.max_samples);
    min_ = std::clamp(b.min_samples, 0, max_);
    const Grid grid = grid_for(max_);

    // The grid's points first, then Halton points of the disc, each in a cell of a square
    // grid that no earlier point holds, so the extra points fill the aperture evenly.
    points_.reserve(size_t(max_));
    for (int i = 0; i < std::min(max_, grid.size); ++i)
        points_.push_back({grid.points[i][0], grid.points[i][1]});
    if (max_ > grid.size) {
        const int cells = 2 * int(std::ceil(std::sqrt(max_ / M_PI))) + 1;
        std::vector<unsigned char> used(size_t(cells) * cells, 0);
        auto cell = [&](const glm::dvec2& p) {
            const int i = std::clamp(int((p.x + 0.5) * cells), 0, cells - 1);
            const int j = std::clamp(int((p.y + 0.5) * cells), 0, cells - 1);
            return size_t(j) * cells + i;
        };
        for (const glm::dvec2& p : points_) used[cell(p)] = 1;
        // Bounded: a disc of radius 0.5 covers more free cells than points are asked for, and
        // after that many tries a point is taken whatever its cell.
        const int tries = 64 * max_ + 1024;
        for (int k = 1; int(points_.size()) < max_; ++k) {
            // Halton point k (bases 2 and 3) mapped evenly onto the disc (measured).
            const double r = 0.5 * std::sqrt(halton(k, 2)), angle = 2 * M_PI * halton(k, 3);
            const glm::dvec2 p(r * std::cos(angle), r * std::sin(angle));
            if (used[cell(p)] && k < tries) continue;
            used[cell(p)] = 1;
            points_.push_back(p);
        }
    }
    batch_end_.assign(size_t(max_), 0);
    int end = 0;
    for (int n : grid.batches)
        if ((end += n) <= max_) batch_end_[size_t(end - 1)] = 1;
    for (end += 4; end <= max_; end += 4) batch_end_[size_t(end - 1)] = 1;

    // The variance a mean of n samples may keep: chi-square quantiles at the confidence,
    // scaled so that the full count of samples is held to `variance` itself. Only the counts
    // that end a batch are ever tested, so only theirs are computed (each is a root search).
    threshold_.assign(size_t(max_), 0);
    if (max_ > 1) {
        const double full = chi_square_upper_quantile(max_ - 1, b.confidence);
        for (int i = 0; i < max_; ++i)
            if (batch_ends(i) && full > 0)
                threshold_[size_t(i)] =
                    b.variance * chi_square_upper_quantile(i + 1, b.confidence) / full;
    }

    jitter_scale_ = 2 * (max_ == grid.size && grid.jitter > 0 ? grid.jitter
                                                              : 0.5 / std::sqrt(double(max_)));
    radius_ = b.aperture / 2;
    direction_length_ = glm::length(camera.direction);
    focal_scale_ = b.focal_distance / direction_length_;
    location_ = camera.location;
    view_ = camera.direction / direction_length_;
    // POV's aperture axes: up × direction and direction × that, in its left-handed frame.
    x_axis_ = glm::normalize(glm::cross(camera.up, camera.direction));
    y_axis_ = glm::normalize(glm::cross(camera.direction, x_axis_));
}

bool FocalBlur::settled(int n, const double s1[4], const double s2[4]) const {
    if (n < min_ || n < 1) return false;
    const double threshold = threshold_[size_t(n - 1)];
    for (int c = 0; c < 4; ++c) {
        const double mean = s1[c] / n;
        if (!((s2[c] / n - mean * mean) / n < threshold)) return false;
    }
    return true;
}

std::optional<Ray> FocalBlur::ray(const CameraModel& camera, double x, double y, int n) const {
    // A sub-pixel offset from the hash of the pixel and the sample's number, then jittered.
    const int seed = int(x * 313 + 11) + int(y * 311 + 17);
    double dx = (2 * (jitter_hash(seed + n) % 16) + 1) / 32.0 - 0.5;
    double dy = (2 * (jitter_hash(seed + n + 1) % 16) + 1) / 32.0 - 0.5;
    double jx, jy;
    jitter2d(dx, dy, jx, jy);
    dx += (jx - 0.5) / 16;
    dy += (jy - 0.5) / 16;
    std::optional<Ray> r = camera.ray(x + dx, y + dy);
    if (!r) return r;
    // The aperture point, jittered by the sample position.
    jitter2d(x + dx + 0.5, y + dy - 0.5, jx, jy);
    const glm::dvec2 a = points_[size_t(n)];
    const glm::dvec3 shift = radius_ * (a.x + jitter_scale_ * jx) * x_axis_ -
                             radius_ * (a.y + jitter_scale_ * jy) * y_axis_;
    // The unblurred ray's point on the focal plane (its length along the view is |direction|
    // scaled to the focal distance), seen from the shifted origin.
    const double along = glm::dot(r->dir, view_);
    const glm::dvec3 d = r->dir * (along > 1e-9 ? direction_length_ / along : direction_length_);
    const glm::dvec3 dir = focal_scale_ * d - shift;
    const double l = glm::length(dir);
    if (!(l > 0) || !std::isfinite(l)) return std::nullopt;
    r->origin = location_ + shift;
    r->dir = dir / l;
    return r;
}

}  // namespace lumen::render

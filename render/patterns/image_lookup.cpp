#include "render/patterns/image_lookup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "render/patterns/wrap.hpp"
#include "scene/image_map.hpp"

namespace lumen::render {
namespace {

namespace pattern = scene::pattern;

constexpr double kEpsilon = 1e-10;
constexpr double kPi = std::numbers::pi;

// r, g, b, filter, transmit of one pixel; a palette index in [0] where indices are wanted.
using Texel = std::array<double, 5>;

// The angle of (x, z) from +x towards +z, in [0, 2 pi).
double longitude(double x, double z) {
    if (z == 0) return x > 0 ? 0 : kPi;
    const double a = std::acos(std::clamp(x / std::sqrt(x * x + z * z), -1.0, 1.0));
    return z < 0 ? 2 * kPi - a : a;
}

// (u, v) in pixels with v growing upwards, before the offset that keeps lookups off texel edges.
std::optional<glm::dvec2> map_point(const pattern::ImageSource& k, const glm::dvec3& p, double w,
                                    double h) {
    switch (k.map_type) {
        case 1: {  // spherical
            const double len = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
            if (len == 0) return std::nullopt;
            const glm::dvec3 n = p / len;
            const double v = (0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / kPi) * h;
            const double u = n.x == 0 && n.z == 0 ? 0 : longitude(n.x, n.z) / (2 * kPi) * w;
            return glm::dvec2(u, v);
        }
        case 2: {  // cylindrical
            if (k.once && (p.y < 0 || p.y > 1)) return std::nullopt;
            const double v = std::fmod(p.y * h, h);
            const double len = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
            if (len == 0) return std::nullopt;
            const double x = p.x / len, z = p.z / len;
            if (x == 0 && z == 0) return std::nullopt;
            return glm::dvec2(longitude(x, z) / (2 * kPi) * w, v);
        }
        case 5: {  // torus of major radius 1
            const double u = longitude(p.x, p.z) / (2 * kPi) * w;
            const double rho = std::sqrt(p.x * p.x + p.z * p.z) - 1;
            const double len = std::sqrt(rho * rho + p.y * p.y);
            double phi = len > 0 ? std::acos(std::clamp(-rho / len, -1.0, 1.0)) : 0;
            if (p.y > 0) phi = 2 * kPi - phi;
            return glm::dvec2(u, phi / (2 * kPi) * h);
        }
        default:  // planar (0, and any other number outside image_map)
            if (k.once && (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1)) return std::nullopt;
            return glm::dvec2(std::fmod(p.x * w, w), std::fmod(p.y * h, h));
    }
}

// A pixel index: wrapped around the image, or clamped to it with `once`.
int tap(int i, int n, bool once) {
    if (once) return std::clamp(i, 0, n - 1);
    const int t = i % n;
    return t < 0 ? t + n : t;
}

// The interpolated value of sample(column, row) at a position, in double, rounded to float.
template <class Sample> Texel interpolated(const pattern::ImageSource& k, const glm::dvec2& at,
                                           Sample&& sample) {
    const image::PovImage& img = k.data->image;
    const int w = img.width, h = img.height;
    auto s = [&](int i, int j) { return sample(tap(i, w, k.once), tap(j, h, k.once)); };
    Texel out{};
    auto add = [&](const Texel& t, double weight) {
        for (int c = 0; c < 5; ++c) out[c] += weight * t[c];
    };
    if (k.interpolate == 2 || k.interpolate == 3 || k.interpolate == 4) {
        // Pixel k's centre lies at k + 0.5: from there the neighbours i - 1 and i are weighed.
        const double x = at.x + 0.5, y = at.y + 0.5;
        const int i = int(x), j = int(y);
        const double p = x - i, q = y - j;
        if (k.interpolate == 3) {  // bicubic over the taps i - 2 .. i + 1
            auto weights = [](double a) {
                const double b = 1 - a;
                return std::array<double, 4>{-0.5 * a * b * b, 0.5 * b * (b * (3 * a + 1) + 1),
                                             0.5 * a * (a * (3 * b + 1) + 1), -0.5 * b * a * a};
            };
            const auto wx = weights(p), wy = weights(q);
            for (int dy = 0; dy < 4; ++dy)
                for (int dx = 0; dx < 4; ++dx) add(s(i - 2 + dx, j - 2 + dy), wx[dx] * wy[dy]);
        } else if (k.interpolate == 2) {
            add(s(i, j), p * q);
            add(s(i - 1, j), (1 - p) * q);
            add(s(i, j - 1), p * (1 - q));
            add(s(i - 1, j - 1), (1 - p) * (1 - q));
        } else {  // normalised distance: each corner by the inverse of its squared distance
            if (p == 0 && q == 0) return s(i - 1, j - 1);
            const double w11 = 1 / ((1 - p) * (1 - p) + (1 - q) * (1 - q)),
                         w01 = 1 / (p * p + (1 - q) * (1 - q)),
                         w10 = 1 / ((1 - p) * (1 - p) + q * q), w00 = 1 / (p * p + q * q);
            const double total = w11 + w01 + w10 + w00;
            add(s(i, j), w11 / total);
            add(s(i - 1, j), w01 / total);
            add(s(i, j - 1), w10 / total);
            add(s(i - 1, j - 1), w00 / total);
        }
    } else {
        out = s(int(at.x), int(at.y));
    }
    for (double& c : out) c = float(c);
    return out;
}

size_t pixel(const image::PovImage& img, int column, int row) {
    return size_t(row) * size_t(img.width) + size_t(column);
}

Texel colour_texel(const pattern::ImageSource& k, int column, int row) {
    const scene::ImageData& data = *k.data;
    const image::PovImage& img = data.image;
    if (img.palette) {
        const uint8_t e = img.indices[pixel(img, column, row)];
        const auto& c = img.colours[e];
        const auto& ft = data.entry_filter_transmit[e];
        return {c[0], c[1], c[2], ft[0], ft[1]};
    }
    const auto& c = img.colours[pixel(img, column, row)];
    return {c[0], c[1], c[2], float(k.filter), (1.0f - c[3]) + float(k.transmit)};
}

// The palette index, or for a true-colour image its red.
Texel index_texel(const pattern::ImageSource& k, int column, int row) {
    const image::PovImage& img = k.data->image;
    const size_t i = pixel(img, column, row);
    return {img.palette ? double(img.indices[i]) : double(img.colours[i][0]), 0, 0, 0, 0};
}

double grey(const Texel& t) { return image::pov_grey(float(t[0]), float(t[1]), float(t[2])); }

}  // namespace

std::optional<glm::dvec2> image_position(const pattern::ImageSource& k, const glm::dvec3& p) {
    if (!k.data) return std::nullopt;
    const image::PovImage& img = k.data->image;
    const double w = img.width, h = img.height;
    const auto uv = map_point(k, p, w, h);
    if (!uv) return std::nullopt;
    const double x = uv->x + kEpsilon, y = uv->y + kEpsilon;
    if (k.once && (x >= w || y >= h || x < 0 || y < 0)) return std::nullopt;
    if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
    // Rows count down from the top of the picture, v up from its bottom.
    return glm::dvec2(wrap(x, w), wrap(-y, h));
}

scene::Colour image_colour(const pattern::ImageSource& k, const glm::dvec2& at) {
    const Texel t = interpolated(k, at, [&](int c, int r) { return colour_texel(k, c, r); });
    return {t[0], t[1], t[2], t[3], t[4]};
}

scene::Colour image_map_colour(const pattern::ImageMap& k, const glm::dvec3& p) {
    const auto at = image_position(k, p);
    if (!at) return {1, 1, 1, 0, 1};
    return image_colour(k, *at);
}

double bump_height(const pattern::BumpMap& k, const glm::dvec2& at) {
    if (k.use_index && k.data->image.palette)
        return std::trunc(interpolated(k, at, [&](int c, int r) { return index_texel(k, c, r); })[0]);
    return grey(interpolated(k, at, [&](int c, int r) { return colour_texel(k, c, r); }));
}

double evaluate(const pattern::ImageMap& k, const glm::dvec3& p) {
    const auto at = image_position(k, p);
    return at ? grey(interpolated(k, *at, [&](int c, int r) { return colour_texel(k, c, r); })) : 0;
}

double evaluate(const pattern::BumpMap& k, const glm::dvec3& p) {
    const auto at = image_position(k, p);
    return at ? bump_height(k, *at) : 0;
}

// use_index still gives the palette colour's grey (measured).
double evaluate(const pattern::ImagePattern& k, const glm::dvec3& p) {
    const auto at = image_position(k, p);
    if (!at) return 0;
    const Texel t = interpolated(k, *at, [&](int c, int r) { return colour_texel(k, c, r); });
    const double v = !k.use_alpha ? grey(t) : k.data->image.alpha ? t[4] : t[0];
    return std::clamp(v, 0.0, 1.0);
}

// Index m of n textures: m mod n beyond the last, and m = n the last one itself.
double evaluate(const pattern::MaterialMap& k, const glm::dvec3& p) {
    const auto at = image_position(k, p);
    if (!at || k.textures <= 0) return 0;
    const double v = interpolated(k, *at, [&](int c, int r) { return index_texel(k, c, r); })[0];
    // Kept in int's range (a float image's red may be huge, or not a number).
    const double scaled = k.data->image.palette ? v : v * 255.0;
    int m = scaled >= 0 ? int(std::min(scaled, 2e9)) : 0;
    if (m > k.textures) m %= k.textures;
    return double(std::max(m, 0));
}

}  // namespace lumen::render

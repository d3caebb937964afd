#include "render/camera.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "render/normal.hpp"

namespace lumen::render {
namespace {

constexpr double kPi = std::numbers::pi;

// v turned by t radians about the unit axis k (Rodrigues).
glm::dvec3 rotated(const glm::dvec3& v, const glm::dvec3& k, double t) {
    return v * std::cos(t) + glm::cross(k, v) * std::sin(t) + k * glm::dot(k, v) * (1 - std::cos(t));
}

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double l = glm::length(v);
    return l > 0 ? v / l : glm::dvec3(0);
}

}  // namespace

CameraModel::CameraModel(const scene::Camera& camera, int width, int height)
    : camera_(camera),
      right_unit_(unit_or_zero(camera.right)),
      up_unit_(unit_or_zero(camera.up)),
      direction_unit_(unit_or_zero(camera.direction)),
      right_length_(glm::length(camera.right)),
      up_length_(glm::length(camera.up)),
      width_(width),
      height_(height) {}

bool CameraModel::project(double x, double y, Ray& ray, glm::dvec3& np) const {
    using scene::CameraType;
    const scene::Camera& c = camera_;
    // POV samples at the pixel centre and flips y so the top row looks up: fx runs 0..1 left
    // to right, fy 0..1 bottom to top.
    const double fx = (x + 0.5) / width_;
    const double fy = (height_ - 0.5 - y) / height_;
    const glm::dvec3 &R = right_unit_, &U = up_unit_, &D = direction_unit_;
    ray.origin = c.location;
    switch (c.type) {
        case CameraType::Perspective:
        case CameraType::Orthographic:
        case CameraType::MeshCamera: {  // mesh_camera is reported unsupported
            const double x0 = fx - 0.5, y0 = fy - 0.5;
            np = {x0, y0, 0};
            if (c.type == CameraType::Orthographic) {
                ray.origin += x0 * c.right + y0 * c.up;
                ray.dir = c.direction;
            } else {
                ray.dir = c.direction + x0 * c.right + y0 * c.up;
            }
            return true;
        }
        case CameraType::Fisheye:
        case CameraType::Omnimax: {
            double x0 = 2 * fx - 1, y0 = 2 * fy - 1;
            if (c.type == CameraType::Fisheye) {
                x0 *= right_length_, y0 *= up_length_;
            } else {
                // The dome's aspect: POV stretches wide images in x and narrow ones in y.
                const double a = right_length_ / up_length_, k = 1.283458;
                if (a > k) x0 *= a / k, y0 = (y0 - 1) / k + 1;
                else if (a > 1) y0 = (y0 - 1) / a + 1;
                else y0 /= a;
            }
            const double r = std::sqrt(x0 * x0 + y0 * y0);
            if (r > 1) return false;
            const double phi = r == 0 ? 0 : x0 < 0 ? kPi - std::asin(y0 / r) : std::asin(y0 / r);
            const double theta = c.type == CameraType::Fisheye
                                     ? r * c.angle * kPi / 360
                                     : 1.411269 * r - 0.09439 * r * r * r + 0.25674 * std::pow(r, 5);
            // Omnimax: nothing below 45 degrees under the horizon (tan 135° = -1).
            if (c.type == CameraType::Omnimax && std::sin(phi) * std::sin(theta) < -std::cos(theta))
                return false;
            np = {phi, theta, 0};
            ray.dir = std::cos(phi) * std::sin(theta) * R + std::sin(phi) * std::sin(theta) * U +
                      std::cos(theta) * D;
            return true;
        }
        case CameraType::UltraWideAngle: {
            const double x0 = (fx - 0.5) * c.angle * kPi / 180;
            const double y0 = (fy - 0.5) * c.angle * (up_length_ / right_length_) * kPi / 180;
            np = {x0, y0, 0};
            ray.dir = std::sin(x0) * R + std::sin(y0) * U + std::cos(x0) * std::cos(y0) * D;
            return true;
        }
        case CameraType::Panoramic: {
            const double a = (1 - fx) * kPi, b = (2 * fy - 1) * kPi / 2;
            const double t = std::fabs(kPi / 2 - std::fabs(b)) < 1e-10 ? (b > 0 ? 1e10 : -1e10)
                                                                        : std::tan(b);
            np = {a, b, 0};
            ray.dir = std::cos(a) * c.right + t * c.up + std::sin(a) * c.direction;
            return true;
        }
        case CameraType::Spherical: {
            const double a = (fx - 0.5) * c.angle * kPi / 180;
            const double b = (fy - 0.5) * c.vertical_angle * kPi / 180;
            np = {a, b, 0};
            ray.dir = rotated(rotated(D, R, -b), U, a);
            return true;
        }
        case CameraType::Cylinder: {
            const double u = fx - 0.5, v = fy - 0.5, theta = c.angle * kPi / 180;
            // Types 1 and 3 span |up| along the axis, 2 and 4 |right|.
            const double s = c.cylinder_type == 1 || c.cylinder_type == 3 ? up_length_ : right_length_;
            // The normal sees the angle along the curved direction, the length along the axis.
            const bool vertical = c.cylinder_type == 1 || c.cylinder_type == 3;
            np = vertical ? glm::dvec3(u * theta, v * s, 0) : glm::dvec3(u * s, v * theta, 0);
            switch (c.cylinder_type) {
                case 1: ray.dir = std::sin(u * theta) * R + v * s * U + std::cos(u * theta) * D; break;
                case 2: ray.dir = u * s * R + std::sin(v * theta) * U + std::cos(v * theta) * D; break;
                case 3:
                    ray.origin += v * s * U;
                    ray.dir = std::sin(u * theta) * R + std::cos(u * theta) * D;
                    break;
                default:
                    ray.origin += u * s * R;
                    ray.dir = std::sin(v * theta) * U + std::cos(v * theta) * D;
                    break;
            }
            return true;
        }
    }
    return false;
}

std::optional<Ray> CameraModel::ray(double x, double y) const {
    Ray r;
    glm::dvec3 np;
    if (!project(x, y, r, np)) return std::nullopt;
    const double l = glm::length(r.dir);
    if (!(l > 0) || !std::isfinite(l)) return std::nullopt;
    r.dir /= l;
    if (camera_.normal) r.dir = perturbed_normal(*camera_.normal, r.dir, np);
    return r;
}

}  // namespace lumen::render

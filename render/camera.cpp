#include "render/camera.hpp"

#include <glm/geometric.hpp>

namespace lumen::render {

CameraModel::CameraModel(const scene::Camera& camera, int width, int height)
    : location_(camera.location),
      direction_(camera.direction),
      right_(camera.right),
      up_(camera.up),
      orthographic_(camera.type == scene::CameraType::Orthographic),
      width_(width),
      height_(height) {}

Ray CameraModel::ray(double x, double y) const {
    // POV samples at the pixel centre and flips y so the top row looks up.
    const double x0 = (x + 0.5) / width_ - 0.5;
    const double y0 = 0.5 - (y + 0.5) / height_;
    if (orthographic_)
        return {location_ + x0 * right_ + y0 * up_, glm::normalize(direction_)};
    return {location_, glm::normalize(direction_ + x0 * right_ + y0 * up_)};
}

}  // namespace lumen::render

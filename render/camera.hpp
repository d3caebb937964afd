// Pixel -> primary ray (POV-Ray 3.7's rules). The scene camera arrives fixed up by the
// interpreter (angle, look_at, orthographic scaling, transforms), so this is only the mapping.
#pragma once
#include "render/ray.hpp"
#include "scene/camera.hpp"

namespace lumen::render {

class CameraModel {
public:
    // width/height are always the full image size, even for partial renders.
    CameraModel(const scene::Camera& camera, int width, int height);

    // Ray through image position (x, y): x from the left, y from the top, in pixel units;
    // (x, y) is the pixel's centre before the half-pixel offset is added, so pixel (i, j)
    // is sampled at ray(i, j) and anti-aliasing passes fractional positions.
    Ray ray(double x, double y) const;

private:
    glm::dvec3 location_, direction_, right_, up_;
    bool orthographic_;
    double width_, height_;
};

}  // namespace lumen::render

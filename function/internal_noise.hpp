// The noise internal functions (internal_noise.cpp), which internal.cpp's table calls:
// f_noise3d, f_noise_generator and the fractal noises, at point p with the parameters after
// x, y, z; and C's (int) conversion as POV-Ray's build does it.
#pragma once
#include <glm/vec3.hpp>

namespace lumen::fn::detail {

int to_int(double v);
double noise3d(const glm::dvec3& p, int scene_generator);
double noise_generator(const glm::dvec3& p, const double* params);
double hetero_mf(const glm::dvec3& p, const double* params);
double ridge(const glm::dvec3& p, const double* params);
double ridged_mf(const glm::dvec3& p, const double* params);

}  // namespace lumen::fn::detail

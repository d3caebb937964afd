// POV-Ray's solid noise and turbulence: the interface the noise issue implements (nothing
// here is defined yet, and nothing calls it). It sits in its own folder, below both render/
// and interp/, because both need it: in render the noise patterns (bozo, granite, wood,
// marble, agate, crackle's jitter, ...), the pattern steps' turbulence and warps
// (scene/pattern_steps.hpp), finish irid turbulence, fog turbulence and media density; in the
// interp the built-in functions f_noise3d, f_noise_generator and vturbulence. When it lands,
// noise/noise.cpp joins a `lumen_module(lumen_noise noise glm::glm)` in CMakeLists.txt that
// lumen_render and lumen_interp link.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern_steps.hpp"

namespace lumen::noise {

// global_settings { noise_generator } and a pattern's own: 1 = POV 3.1's original noise,
// 2 = range-corrected (the default), 3 = Perlin's improved noise. A pattern's 0 means "the
// global setting".
enum class Generator { Original = 1, RangeCorrected = 2, Perlin = 3 };

// Noise at p in [0, 1] (POV's Noise()).
double noise(const glm::dvec3& p, Generator generator);
// A noise vector at p, each component in [-1, 1] (POV's DNoise()).
glm::dvec3 dnoise(const glm::dvec3& p, Generator generator);
// Scalar turbulence (POV's Turbulence()): noise summed over `octaves`, each octave at
// lambda times the frequency and omega times the amplitude of the one before.
double turbulence(const glm::dvec3& p, const scene::TurbulenceParams& params,
                  Generator generator);
// The displacement a turbulence warp adds to p before its amount scales it.
glm::dvec3 dturbulence(const glm::dvec3& p, const scene::TurbulenceParams& params,
                       Generator generator);

}  // namespace lumen::noise

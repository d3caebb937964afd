// POV-Ray's solid noise and turbulence, reproduced to the bit. It sits in its own folder, below
// both render/ and interp/, because both need it: in render the noise patterns (bozo, granite,
// wood, marble, agate, crackle, cells, ripples, waves, ...), the pattern steps' turbulence
// (scene/pattern_steps.hpp), normal perturbation, finish irid and fog turbulence; in the
// interp the built-in functions f_noise3d and vturbulence. Every table is built once per
// process; no call allocates.
#pragma once
#include <span>

#include <glm/vec3.hpp>

#include "scene/pattern_steps.hpp"

namespace lumen::noise {

// global_settings { noise_generator } and a pattern's own: 1 = POV 3.1's original noise,
// 2 = range-corrected (the default), 3 = Perlin's improved noise. A pattern's 0 means "the
// global setting".
enum class Generator { Original = 1, RangeCorrected = 2, Perlin = 3 };

// The generator a pattern uses: its own `noise_generator` (1..3), else the scene's.
inline Generator resolve_generator(int pattern_generator, int scene_generator) {
    const int g = pattern_generator >= 1 && pattern_generator <= 3 ? pattern_generator
                                                                    : scene_generator;
    return g >= 1 && g <= 3 ? Generator(g) : Generator::RangeCorrected;
}

// Noise at p in [0, 1] (POV's Noise()).
double noise(const glm::dvec3& p, Generator generator);
// A noise vector at p, each component about [-1, 1] (POV's DNoise()). It has no generator:
// POV's displacements and bump directions always use the original lattice.
glm::dvec3 dnoise(const glm::dvec3& p);
namespace detail {
// dnoise runs four lanes wide where the processor has AVX2; this is its two-lane form, which
// runs elsewhere (exposed so that tests check that both give POV's bits).
glm::dvec3 dnoise_in_pairs(const glm::dvec3& p);
}  // namespace detail
// Scalar turbulence (POV's Turbulence()): noise summed over `octaves`, each octave at
// lambda times the frequency and omega times the amplitude of the one before. params.amount
// is not used (the caller scales by it).
double turbulence(const glm::dvec3& p, const scene::TurbulenceParams& params,
                  Generator generator);
// The vector turbulence (POV's DTurbulence()): dnoise summed over the octaves the same way.
// A turbulence step adds it, scaled component-wise by the amount, to the point.
glm::dvec3 dturbulence(const glm::dvec3& p, const scene::TurbulenceParams& params);

// POV's hash of an integer lattice cell, 0..4095; each coordinate is taken mod 4096 (two's
// complement, so -1 is 4095).
int hash3d(int a, int b, int c);
// POV's PatternRands, 32768 uniform numbers in [0, 1) (boost mt19937 with its default seed);
// the index is taken mod 32768.
double pattern_rand(int i);

// The sources and frequencies of the waves and ripples patterns and normals. Source i is the
// unit dnoise vector at <i, 0, 0>; the frequencies come from their own generator. They do not
// depend on the count, so one table serves every global_settings { number_of_waves }.
struct Wave {
    glm::dvec3 source;
    double frequency;
};
inline constexpr int kMaxWaves = 10000;
// The first `count` waves; a count <= 0 is 1 (as in POV), one above kMaxWaves is kMaxWaves.
std::span<const Wave> waves(int count);

}  // namespace lumen::noise

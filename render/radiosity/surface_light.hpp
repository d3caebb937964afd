// What radiosity needs of a surface at one point, meshed or not: its diffuse reflectance ρ
// (diffuse × pigment, layers stacked as the tracer stacks them), emission E and brilliance, and the direct light H as
// POV-Ray's radiosity rays see it.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "render/intersector.hpp"
#include "render/lights.hpp"
#include "render/trace_state.hpp"
#include "scene/scene.hpp"

namespace lumen::render::radiosity {

struct SurfaceMaterial {
    glm::dvec3 rho{0};       // diffuse × pigment × opacity
    glm::dvec3 emission{0};  // (emission + ambient as emission) × pigment × opacity
    double brilliance = 1;   // direct light goes with cos^brilliance
};

// POV-Ray 3.7 lets `ambient` act as emission under radiosity in scenes of #version < 3.7
// (a plane of ambient 0.2 under a sky of ambient 1 shows both terms; from 3.7 on ambient is
// 0): the factor ambient is multiplied by, ambient_light there and 0 from 3.7 on.
glm::dvec3 ambient_emission(const scene::Scene& scene);

// The material of `texture` at world point p: its layers through the filter and transmit of
// those above them; the top layer's brilliance.
SurfaceMaterial surface_material(const scene::LayeredTexture* texture, const glm::dvec3& p,
                                 const glm::dvec3& ambient_emission);

// True when every layer has diffuse 0 wherever it is (every texture_map entry too): such a
// surface only emits, and needs no light of its own.
bool never_diffuse(const scene::LayeredTexture* texture);

// Direct light reaching point p (already lifted off the surface) on the side of unit normal n:
// POV's radiosity rays see area lights as point lights at their centre, spotlight falloff and
// fade apply, shadows are traced, the diffuse term goes with cos^brilliance. With `back`, the
// light on the side of -n is added there, each light sampled once for both sides.
glm::dvec3 direct_light_at(const std::vector<LightSource>& lights, const Intersector& geometry,
                           const glm::dvec3& p, const glm::dvec3& n, double brilliance,
                           TraceCounters& counters, glm::dvec3* back = nullptr);

// The same on the side of n alone, with one shadow ray where direct_light_at traces one per
// light: the lights' unshadowed terms are summed, one light is picked with probability its
// share of the sum (by `u` in [0, 1)) and its visibility stands for all (an unbiased
// estimate; shadowless lights are added whole). A gather that lands on many points averages
// the choice away at a fraction of the rays (radiosity/cornell.pov's 16 lights).
glm::dvec3 direct_light_one_of(const std::vector<LightSource>& lights,
                               const Intersector& geometry, const glm::dvec3& p,
                               const glm::dvec3& n, double brilliance, double u,
                               TraceCounters& counters);

}  // namespace lumen::render::radiosity

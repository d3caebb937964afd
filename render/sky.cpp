#include "render/sky.hpp"

#include "render/pigment.hpp"
#include "render/texture_layers.hpp"

namespace lumen::render {

glm::dvec3 sky_colour(const scene::Scene& scene, const glm::dvec3& dir, glm::dvec3* through) {
    // The interpreter has already premultiplied the rgb by (1 − transmit).
    const scene::Colour& bg = scene.background;
    const glm::dvec3 background(bg.r, bg.g, bg.b);
    if (through) *through = glm::dvec3(1);
    if (!scene.sky_sphere || scene.sky_sphere->pigments.empty()) return background;
    const scene::SkySphere& sky = *scene.sky_sphere;
    const glm::dvec3 p = sky.transform.is_identity() ? dir : sky.transform.inv_vector(dir);
    glm::dvec3 acc(0), filter(1);
    for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
        const scene::Colour c = evaluate_pigment(it->get(), p);
        acc += filter * glm::dvec3(c.r, c.g, c.b) * (1 - c.f - c.t) * sky.emission;
        filter *= layer_filter(c);
    }
    if (through) *through = filter;
    return acc + filter * background;
}

}  // namespace lumen::render

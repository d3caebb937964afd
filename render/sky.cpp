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
    if (scene.language_version < 3.7) {
        // Before #version 3.7 POV-Ray's sky does not tint: the light through the layers is the
        // product of their filters plus the product of their transmits (measured: a filtering
        // layer over a transmitting one hides what is under both).
        double filtered = 1, transmitted = 1;
        for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
            const scene::Colour c = evaluate_pigment(it->get(), p);
            const double through_here = it == sky.pigments.rbegin() ? 1 : filtered + transmitted;
            acc += through_here * glm::dvec3(c.r, c.g, c.b) * (1 - c.f - c.t) * sky.emission;
            filtered *= c.f, transmitted *= c.t;
        }
        filter = glm::dvec3(filtered + transmitted);
    } else {
        for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
            const scene::Colour c = evaluate_pigment(it->get(), p);
            acc += filter * glm::dvec3(c.r, c.g, c.b) * (1 - c.f - c.t) * sky.emission;
            filter *= layer_filter(c);
        }
    }
    if (through) *through = filter;
    return acc + filter * background;
}

}  // namespace lumen::render

// POV-Ray's TraceRay: nearest hit, layered shading, reflection,
// refraction with interior lists, total internal reflection, fade, continued rays, sky and fog.
#pragma once
#include <vector>

#include "render/indirect_light.hpp"
#include "render/interior_list.hpp"
#include "render/intersector.hpp"
#include "render/lights.hpp"
#include "render/normal_frame.hpp"
#include "render/photons/photon_pass.hpp"
#include "render/shading.hpp"
#include "render/trace_state.hpp"
#include "scene/scene.hpp"

namespace lumen::render {

// Colour carried back along a ray: rgb in the working space plus the transmit (alpha) channel.
struct RayColour {
    glm::dvec3 rgb{0};
    double transmit = 0;
};

struct TraceOptions {
    int quality = 9;
    bool alpha = false;  // +UA: the background is transparent
    const IndirectLight* indirect = nullptr;  // radiosity; null: none
    const PhotonPass* photons = nullptr;      // the photon map; null: none
};

class RenderFrame;

class Tracer {
public:
    // Traces the frame's scene through its geometry and lights (the frame must outlive it).
    Tracer(const RenderFrame& frame, const TraceOptions& options);
    // The same over another intersector (tests); prepares the scene's lights itself. `scene`
    // and `geometry` must outlive the tracer.
    Tracer(const scene::Scene& scene, const Intersector& geometry, const TraceOptions& options);

    // Colour seen along a camera ray.
    RayColour trace_primary(const Ray& ray, ThreadState& state) const;

private:
    enum class RayKind { Image, Reflection, Other };
    struct Context;  // one ray's level, weight, interiors and kind

    void init(const std::vector<LightSource>& lights);  // the settings both constructors share
    RayColour trace(const Ray& ray, const Context& ctx, ThreadState& state, double* depth) const;
    // Where the texture is evaluated: the hit point with no normal frame, or within a
    // texture_map's entry the map's pattern point and its frame (render/normal_frame.hpp).
    struct TexturePoint {
        glm::dvec3 point;
        NormalFrame frame;
    };
    RayColour shade_blob(const Ray& ray, const Hit& hit, const TexturePoint& at,
                         const Context& ctx, ThreadState& state) const;
    RayColour shade(const Ray& ray, const Hit& hit, const TexturePoint& at, const Context& ctx,
                    ThreadState& state) const;
    RayColour shade_layers(const Ray& ray, const Hit& hit, const scene::LayeredTexture* texture,
                           const TexturePoint& at, const Context& ctx, ThreadState& state) const;
    RayColour sky(const glm::dvec3& dir) const;
    void apply_fog(RayColour& c, const Ray& ray, double depth, const InteriorList& interiors) const;
    void apply_rainbows(RayColour& c, const Ray& ray, double depth, const InteriorList& interiors,
                        ThreadState& state) const;
    // The media of the interiors the ray is in (up to a hit) and the atmosphere, POV-Ray's
    // order: object media first, each pass over the whole segment.
    void apply_media(RayColour& c, const Ray& ray, double depth, bool hit,
                     const InteriorList& interiors, ThreadState& state) const;
    bool find_hit(const Ray& ray, RayKind kind, Hit& hit) const;

    const scene::Scene& scene_;
    const Intersector& geometry_;
    TraceOptions options_;
    std::vector<LightSource> own_lights_;  // prepared here when no frame holds them
    LightingEnv env_;
    bool media_ = false;  // the scene has media (in an interior or the atmosphere)
    // The interiors around the camera, where primary rays start (POV-Ray tests every object
    // for the camera inside it: fog, media and fresnel reflection depend on them).
    InteriorList camera_interiors_;
    std::vector<const scene::Media*> atmosphere_;
    int max_level_;
    double adc_bailout_;
    bool legacy_opacity_;
};

}  // namespace lumen::render

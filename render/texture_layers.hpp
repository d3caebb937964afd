// Resolving a (layered, possibly patterned) texture at a point into plain layers, and the
// light filter of a surface for shadow rays.
#pragma once
#include <new>

#include <glm/vec3.hpp>

#include "render/hit.hpp"
#include "render/normal_frame.hpp"
#include "render/pattern.hpp"
#include "scene/texture.hpp"

namespace lumen::render {

// One plain layer at a point: pigment colour, finish and normal.
// (No default member initialisers: arrays of layers live on the stack of every shaded hit.)
struct ResolvedLayer {
    scene::Colour colour;
    const scene::Finish* finish;  // never null after resolve
    const scene::Normal* normal;  // null: no perturbation
    // Where the normal is evaluated, and through which frame: the point given and no frame, or
    // within a texture_map's entry the map's pattern point and its frame.
    glm::dvec3 point;
    NormalFrame frame;
    // The texture this layer was resolved from, and whether its colour read the surface
    // normal (slope, aoi): then a normal perturbed before the layer is coloured changes it.
    const scene::Texture* source;
    bool reads_normal;
};

const scene::Finish& default_finish();

// The texture a ray travelling along `dir` sees at `hit`: the interior_texture when the ray
// meets the back of the surface (the outward normal faces away from where it comes from),
// else the texture.
inline const scene::LayeredTexture* facing_texture(const Hit& hit, const glm::dvec3& dir) {
    const glm::dvec3& n = hit.normal;
    if (hit.interior_texture && n.x * dir.x + n.y * dir.y + n.z * dir.z > 0)
        return hit.interior_texture;
    return hit.texture;
}

// Plain texture -> its layer. A patterned texture used as one layer of several is resolved by
// blending its entries' pigments and taking the finish/normal of the heavier entry (POV blends
// whole shading results only for a single patterned texture; the tracer does that itself).
// `surface` (null: none) reaches the slope and aoi patterns.
ResolvedLayer resolve_layer(const scene::Texture& texture, const glm::dvec3& p,
                            const SurfacePoint* surface = nullptr);

// Top-first list of the resolved layers of `layers` (bottom-first in the scene graph); a null
// or empty texture is the default one (black, default finish).
// Uninitialised storage: this lives on the stack of every shaded hit, and zeroing all
// kMax layers showed up in profiles.
class ResolvedLayers {
public:
    static constexpr int kMax = 16;
    int count() const { return count_; }
    const ResolvedLayer& operator[](int i) const {
        return *std::launder(reinterpret_cast<const ResolvedLayer*>(storage_) + i);
    }
    void clear() { count_ = 0; }
    bool full() const { return count_ == kMax; }
    void add(const ResolvedLayer& l) { new (storage_ + sizeof(ResolvedLayer) * count_++) ResolvedLayer(l); }

private:
    int count_ = 0;
    alignas(ResolvedLayer) unsigned char storage_[kMax * sizeof(ResolvedLayer)];
};
void resolve_layers(const scene::LayeredTexture* layers, const glm::dvec3& p, ResolvedLayers& out,
                    const SurfacePoint* surface = nullptr);

// Product over layers of (rgb·filter + transmit): the light a surface lets through.
glm::dvec3 surface_filter(const scene::LayeredTexture* layers, const glm::dvec3& p,
                          const SurfacePoint* surface = nullptr);

// Whether any pattern of the layers (their pigments, normals, maps and entries) is under
// uv_mapping: only then does a hit need its (u, v).
bool uses_uv_mapping(const scene::LayeredTexture* layers);

// False when surface_filter is 0 at every point (no colour the texture can take has filter
// or transmit); true when it may let light through somewhere.
bool may_pass_light(const scene::LayeredTexture* layers);

// True when surface_filter is exactly 1 at every point: every layer a solid colour whose
// rgb·f + t is 1 in each channel (patterned layers are not looked into).
bool passes_all_light(const scene::LayeredTexture* layers);

// The filter colour of one layer: rgb·f + t per channel.
inline glm::dvec3 layer_filter(const scene::Colour& c) {
    return glm::dvec3(c.r, c.g, c.b) * c.f + glm::dvec3(c.t);
}

}  // namespace lumen::render

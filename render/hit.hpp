// The nearest intersection found by Geometry, with everything shading needs resolved.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/object.hpp"

namespace lumen::render {

struct BlobShape;

struct Hit {
    double t = 0;                 // distance along the (unit) ray
    glm::dvec3 point{0};          // world-space hit point
    glm::dvec3 normal{0, 1, 0};   // world-space unit normal, outward (already flipped for
                                  // `inverse`), NOT yet flipped to face the ray; smooth
                                  // triangles give the interpolated normal
    glm::dvec2 uv{0};             // the surface's (u, v) (render/surface_uv.hpp), set only
                                  // when the texture uses uv_mapping
    const scene::Object* object = nullptr;  // the primitive that was hit (flags, interior)
    // The texture to shade with after CSG inheritance: the primitive's own, else the nearest
    // CSG ancestor's; null means the default texture. For meshes, the triangle's texture.
    const scene::LayeredTexture* texture = nullptr;
    // interior_texture after the same inheritance (null = none): shades the back side.
    const scene::LayeredTexture* interior_texture = nullptr;
    // Interior after inheritance (null = default interior). Its identity also tells which
    // "inside" the ray enters or leaves (POV-Ray's interior list).
    const scene::Interior* interior = nullptr;
    const void* interior_id = nullptr;  // stable identity of the interior owner (for lists)
    // Object flags after CSG inheritance: set when the primitive or any CSG ancestor has it
    // (POV copies a CSG's flags to its children, so `union { ... no_image }` hides them all).
    // Use these rather than object->no_image and friends.
    bool no_image = false, no_reflection = false, double_illuminate = false,
         no_radiosity = false, hollow = false;
    // Photon flags after CSG inheritance (null: the defaults) and the outermost photon target
    // among the primitive and its CSG ancestors (null: none), which photons are shot at.
    const scene::ObjectPhotons* photons = nullptr;
    const scene::Object* photon_target = nullptr;
    // The innermost light_group it lies in (0: none) and that group's global_lights.
    uint32_t light_group = 0;
    bool global_lights = true;
    // A blob whose components have textures of their own, which shading blends by their
    // densities at `local_point` (the hit in the blob's space); null otherwise.
    const BlobShape* textured_blob = nullptr;
    glm::dvec3 local_point{0};
    // The normal the slope and aoi patterns see while this hit is shaded: the surface normal
    // facing the ray until a layer's normal perturbs it, then the last perturbed normal
    // (POV-Ray keeps one per intersection, so in nested texture_maps an entry shaded later
    // sees the normal of the one before). Null: the facing surface normal.
    glm::dvec3* pattern_normal = nullptr;
};

}  // namespace lumen::render

// The photon pass of a frame (POV-Ray 3.7's photon mapping): photons shot from every light at
// every target, traced through reflection and refraction, stored where they land on
// collecting surfaces; the map the tracer gathers caustics from.
#pragma once
#include <cstdint>
#include <memory>

#include "render/photons/photon_map.hpp"

namespace lumen::render {

class RenderFrame;

struct PhotonPass {
    PhotonMap surface;       // photons on surfaces, as a kd-tree
    GatherSettings gather;   // how the tracer gathers them (radius chosen after shooting)
    PhotonMap media;         // photons left along paths through scattering media
    GatherSettings media_gather;
    double spacing = 0;      // the surface spacing used (given, or estimated from count)
    uint64_t shot = 0;       // photons shot (POV-Ray's statistic)
};

// Shoots the frame's photons on `threads` threads (0: all cores); null when the scene has no
// photons block or it gathers nothing (gather Max 0). Deterministic: the same map for any
// thread count.
std::unique_ptr<PhotonPass> shoot_photons(const RenderFrame& frame, int threads);

}  // namespace lumen::render

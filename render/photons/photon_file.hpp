// photons { save_file "F" } and { load_file "F" }: a photon map written after shooting and
// read back in place of shooting (a still re-rendered, an animation whose lights and targets
// stay put). lumen's own format, not POV-Ray's: a text line "lumen-photons 1", the photon
// count, photons shot and spacing, then the photons as stored in memory (this machine's byte
// order). The path is taken as written, relative to the working directory, as POV-Ray does.
#pragma once
#include <string>

#include "base/diagnostics.hpp"
#include "render/photons/photon_pass.hpp"

namespace lumen::render {

// Writes the pass's map, shot count and spacing whole or not at all (base/whole_file.hpp).
// Throws LumenError at `loc` when it cannot.
void save_photons(const PhotonPass& pass, const std::string& path, const SourceLoc& loc);

// Reads a file save_photons wrote into `pass` (its map in the saved kd-tree order). Throws
// LumenError at `loc` when the file is missing, of another kind, truncated or damaged (POV-Ray
// stops too: "Could not load photon map").
void load_photons(PhotonPass& pass, const std::string& path, const SourceLoc& loc);

}  // namespace lumen::render

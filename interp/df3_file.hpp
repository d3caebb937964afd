// POV-Ray's df3 density files: a big-endian 16-bit header nx, ny, nz, then the voxels (x
// fastest, then y, then z) in 1, 2 or 4 big-endian bytes each, told apart by the file's size.
#pragma once
#include <memory>
#include <string>

#include "base/source.hpp"
#include "scene/pattern_kinds.hpp"

namespace lumen::interp {

// The file's voxels scaled to [0, 1]. Throws LumenError (at `loc`) for an unreadable file or
// one whose size fits no voxel width.
std::shared_ptr<const scene::pattern::DensityGrid> read_df3(const std::string& path, SourceLoc loc);

}  // namespace lumen::interp

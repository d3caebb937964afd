// Saving and loading a radiosity solution (POV's +RF keys, lumen's meaning): a text header
// (magic, version, scene key, unknown count, bounces) and the B, G and indirect values as
// text with full precision. Loading a file made for another scene or mesh is an error.
#pragma once
#include <cstdint>
#include <string>

#include "render/radiosity/scene_solution.hpp"

namespace lumen::render::radiosity {

// The file format's version (2: the indirect light inside B). Part of the solution key, so a
// Radiosity_Store folder's files from another format have other names and are solved anew.
inline constexpr int kSolutionFileVersion = 2;

void save_solution(const Solution& solution, const std::string& path);

// Throws LumenError when the file is missing, malformed, or was made for another scene
// (`scene_key`) or mesh (`unknowns`).
Solution load_solution(const std::string& path, uint64_t scene_key, size_t unknowns);

}  // namespace lumen::render::radiosity

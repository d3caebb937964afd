// tests/differential/scenes.txt: one scene per line,
//   <scene> <width>x<height> <min PSNR dB> [options for both renderers...]
// '#' starts a comment. A scene path starting with "povray:" is relative to POV-Ray's sample
// scene folder; other paths are relative to the repository root.
#pragma once
#include <string>
#include <vector>

namespace lumen::differential {

struct SceneEntry {
    std::string scene;  // as written in scenes.txt
    std::string path;   // resolved file path
    std::string name;   // test name: letters, digits and '_' ("examples_showcase")
    int width = 0, height = 0;
    double min_psnr = 0;
    std::vector<std::string> options;
    int line = 0;
};

// Throws std::runtime_error with "scenes.txt:LINE: ..." on a malformed line.
std::vector<SceneEntry> read_scene_list(const std::string& list_path, const std::string& root,
                                        const std::string& povray_scenes_dir);

}  // namespace lumen::differential

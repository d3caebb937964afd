#include "tests/differential/scene_list.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lumen::differential {
namespace {

std::string test_name(const std::string& scene) {
    std::string s = scene;
    if (s.size() > 4 && s.compare(s.size() - 4, 4, ".pov") == 0) s.resize(s.size() - 4);
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return s;
}

}  // namespace

std::vector<SceneEntry> read_scene_list(const std::string& list_path, const std::string& root,
                                        const std::string& povray_scenes_dir) {
    std::ifstream in(list_path);
    if (!in) throw std::runtime_error("cannot read " + list_path);
    std::vector<SceneEntry> entries;
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
        ++line_no;
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        SceneEntry e;
        std::string size;
        if (!(words >> e.scene)) continue;  // blank or comment
        const auto fail = [&](const std::string& why) {
            throw std::runtime_error(list_path + ":" + std::to_string(line_no) + ": " + why);
        };
        if (!(words >> size) || std::sscanf(size.c_str(), "%dx%d", &e.width, &e.height) != 2 ||
            e.width < 1 || e.height < 1)
            fail("expected a size such as 320x240 after the scene");
        if (!(words >> e.min_psnr)) fail("expected the minimum PSNR in dB after the size");
        for (std::string opt; words >> opt;) e.options.push_back(opt);
        const std::string prefix = "povray:";
        e.path = e.scene.rfind(prefix, 0) == 0
                     ? (std::filesystem::path(povray_scenes_dir) / e.scene.substr(prefix.size())).string()
                     : (std::filesystem::path(root) / e.scene).string();
        e.name = test_name(e.scene);
        e.line = line_no;
        entries.push_back(std::move(e));
    }
    return entries;
}

}  // namespace lumen::differential

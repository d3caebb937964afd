#include "render/radiosity/solution_io.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "base/diagnostics.hpp"
#include "base/whole_file.hpp"

namespace lumen::render::radiosity {

namespace {

constexpr const char* kMagic = "lumen-radiosity-solution";

[[noreturn]] void bad_file(const std::string& path, const std::string& why) {
    throw LumenError({}, "radiosity solution file '" + path + "': " + why);
}

void write_solution(const Solution& s, std::ostream& out) {
    out << kMagic << ' ' << kSolutionFileVersion << '\n'
        << "scene " << s.scene_key << '\n'
        << "unknowns " << s.B.size() << '\n'
        << "bounces " << s.bounces << '\n';
    char buf[256];
    for (size_t u = 0; u < s.B.size(); ++u) {
        // A solve without form factors has no G: zeros (needs_form_factors says so on load).
        const glm::dvec3 g = u < s.G.size() ? s.G[u] : glm::dvec3(0);
        const glm::dvec3 i = u < s.indirect.size() ? s.indirect[u] : glm::dvec3(0);
        std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
                      s.B[u].x, s.B[u].y, s.B[u].z, g.x, g.y, g.z, i.x, i.y, i.z);
        out << buf;
    }
    out << "end\n";
}

}  // namespace

void save_solution(const Solution& s, const std::string& path) {
    const std::string why = write_whole_file(path, [&](std::ostream& out) { write_solution(s, out); });
    if (!why.empty()) bad_file(path, why);
}

Solution load_solution(const std::string& path, uint64_t scene_key, size_t unknowns) {
    std::ifstream in(path);
    if (!in) bad_file(path, "cannot be read");
    std::string magic, word;
    int version = 0;
    Solution s;
    size_t n = 0;
    if (!(in >> magic >> version) || magic != kMagic) bad_file(path, "not a lumen radiosity solution");
    if (version != kSolutionFileVersion)
        bad_file(path, "version " + std::to_string(version) + " (lumen reads " +
                           std::to_string(kSolutionFileVersion) + ")");
    if (!(in >> word >> s.scene_key) || word != "scene" || !(in >> word >> n) ||
        word != "unknowns" || !(in >> word >> s.bounces) || word != "bounces")
        bad_file(path, "malformed header");
    if (s.scene_key != scene_key)
        bad_file(path, "made for another scene (only the camera may differ)");
    if (n != unknowns)
        bad_file(path, "made for " + std::to_string(n) + " unknowns, this mesh has " +
                           std::to_string(unknowns) + " (another Radiosity_Patch_Size?)");
    s.B.resize(n);
    s.G.resize(n);
    s.indirect.resize(n);
    for (size_t u = 0; u < n; ++u) {
        auto& b = s.B[u];
        auto& g = s.G[u];
        auto& i = s.indirect[u];
        if (!(in >> b.x >> b.y >> b.z >> g.x >> g.y >> g.z >> i.x >> i.y >> i.z))
            bad_file(path, "truncated");
        if (!std::isfinite(b.x + b.y + b.z + g.x + g.y + g.z + i.x + i.y + i.z))
            bad_file(path, "non-finite value");
    }
    if (!(in >> word) || word != "end") bad_file(path, "truncated");
    return s;
}

}  // namespace lumen::render::radiosity

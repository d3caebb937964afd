#include "base/file_resolver.hpp"

#include <filesystem>

namespace lumen {
namespace fs = std::filesystem;

namespace {

// Extensions POV-Ray tries after the name as written, when the name has none.
std::vector<std::string> extensions(FileResolver::Kind kind) {
    switch (kind) {
        case FileResolver::Kind::Include: return {".inc"};
        case FileResolver::Kind::Image:
            return {".png", ".tga", ".ppm", ".pgm", ".gif", ".jpg", ".jpeg", ".tif", ".tiff",
                    ".exr", ".hdr", ".bmp"};
        case FileResolver::Kind::Font: return {".ttf"};
        case FileResolver::Kind::DensityFile: return {".df3"};
        case FileResolver::Kind::DataFile: return {};
    }
    return {};
}

bool usable(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

}  // namespace

std::string FileResolver::find(const std::string& name, Kind kind) const {
    if (name.empty()) return {};
    const fs::path p(name);
    std::vector<fs::path> names{p};
    if (!p.has_extension())
        for (const std::string& e : extensions(kind)) names.emplace_back(name + e);
    std::vector<fs::path> dirs;
    if (p.is_absolute()) {
        dirs.emplace_back();
    } else {
        dirs.emplace_back(".");  // POV-Ray looks in the working folder first (measured)
        dirs.emplace_back(path_.scene_dir);
        for (const std::string& d : path_.library_paths) dirs.emplace_back(d);
        if (!path_.system_include_dir.empty()) dirs.emplace_back(path_.system_include_dir);
    }
    for (const fs::path& d : dirs)
        for (const fs::path& n : names) {
            const fs::path candidate = d.empty() ? n : d / n;
            if (usable(candidate)) return candidate.lexically_normal().string();
        }
    return {};
}

}  // namespace lumen

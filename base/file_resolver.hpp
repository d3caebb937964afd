// Finds the files a scene names (#include, and the images, fonts, density files and #fopen
// files of the builders) in POV-Ray's search order: an absolute name as it is; otherwise the
// working folder (POV-Ray's first place, where #write puts files), the folder of the scene file
// (lumen's addition: POV-Ray needs it in +L), then each +L / Library_Path folder in the order
// given, then POV-Ray's installed include folder. Each folder is tried with the name as written and then
// with each of the kind's extensions added (POV's `#include "colors"` finds colors.inc).
#pragma once
#include <string>
#include <vector>

namespace lumen {

struct SearchPath {
    std::string scene_dir = ".";
    std::vector<std::string> library_paths;
    std::string system_include_dir;  // empty = none
};

class FileResolver {
public:
    // What is looked for: the extensions POV adds to a name that has none.
    enum class Kind { Include, Image, Font, DensityFile, DataFile };

    FileResolver() = default;
    explicit FileResolver(SearchPath path) : path_(std::move(path)) {}

    // The path of the first regular file found, normalised; empty when there is none.
    std::string find(const std::string& name, Kind kind) const;

    const SearchPath& path() const { return path_; }

private:
    SearchPath path_;
};

}  // namespace lumen

// Per-scene results of the differential suite, kept as small files so parallel tests never
// share one, and the HTML index built from all of them.
#pragma once
#include <string>
#include <vector>

namespace lumen::differential {

struct Result {
    std::string name, scene, options;
    std::string reference_image, lumen_image, heat_map;  // relative to the output folder
    double min_psnr = 0, psnr = 0;
    int max_error = 0;
    double differing_fraction = 0;
    double lumen_seconds = 0, povray_seconds = 0;
    bool passed = false;
    std::string message;  // why it failed (lumen error, size mismatch, ...)
};

// Writes <out>/results/<name>.txt, then rebuilds <out>/index.html from the results files of the
// scenes in `listed` (scenes dropped from the list are left out), written to a temporary file
// and renamed, so readers never see half a page.
void record_result(const std::string& out_dir, const Result& r,
                   const std::vector<std::string>& listed);

}  // namespace lumen::differential

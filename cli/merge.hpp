// `lumen merge`: partial renders of one image (+SR/+ER/+SC/+EC, by hand or by `lumen farm`)
// joined into the whole. A partial render is written at the full size with its margins zero,
// so each pixel comes from the part that rendered it: the one whose samples are not all zero.
#pragma once
#include <string>
#include <vector>

namespace lumen::cli {

struct MergeResult {
    int width = 0, height = 0;
    size_t blank = 0;  // pixels no part rendered (or every part rendered black)
};

// A part: a whole-size partial render (at 0, 0), or a cropped one (Output_Crop) whose
// top-left pixel is (x, y) of the whole.
struct MergePart {
    std::string path;
    int x = 0, y = 0;
};

// Reads every part (files lumen writes: png, ppm, tif, exr, hdr; all of one format) into a
// width x height image (0: the first part's size) and writes `output`, of the same type,
// completely or not at all. Throws LumenError naming the part when one cannot be read,
// differs in format from the first, does not fit, or gives a pixel another part rendered
// differently (overlapping parts must agree).
MergeResult merge_parts(const std::vector<MergePart>& parts, const std::string& output,
                        int width = 0, int height = 0);

// The subcommand: `lumen merge OUTPUT [--size=W,H] [--at=X,Y] PART...`. Returns the exit status.
int run_merge(const std::vector<std::string>& args);

}  // namespace lumen::cli

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

// Reads every part (files lumen writes: png, ppm, tif, exr, hdr; all of one size and format)
// and writes `output`, of the same type, completely or not at all. Throws LumenError naming
// the part when one cannot be read, differs in size or format from the first, or gives a
// pixel another part rendered differently (overlapping parts must agree).
MergeResult merge_parts(const std::vector<std::string>& parts, const std::string& output);

// The subcommand: `lumen merge OUTPUT PART...`. Returns the exit status.
int run_merge(const std::vector<std::string>& args);

}  // namespace lumen::cli

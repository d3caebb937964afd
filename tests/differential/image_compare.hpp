// Comparing two renders over 8-bit RGB: PSNR, largest error and a difference heat map.
#pragma once
#include <string>

namespace lumen::differential {

struct Comparison {
    int width = 0, height = 0;
    double psnr = 0;  // dB; infinity when the images are identical
    int max_error = 0;  // largest |a-b| over all channels, in 8-bit levels
    double differing_fraction = 0;  // share of pixels with any channel differing
    double mean_error = 0;  // mean |a-b| over pixels and channels on a 0..1 scale (idiff -a)
    // Pixels black in the candidate (every channel <= 4 levels) where the reference is lit
    // all around (the largest channel of the pixel and of its 8 neighbours >= 32 levels): a surface
    // left without light, not an edge one pixel off.
    int dark_where_lit = 0;
};

// Loads both images (any format OpenImageIO reads), quantised to 8 bits, and compares their
// RGB channels. Writes a heat map of the per-pixel largest difference to `heat_map_path`
// (black = equal, through red and yellow to white = 64 levels or more). Throws
// std::runtime_error if an image cannot be read or the sizes differ.
Comparison compare_images(const std::string& reference, const std::string& candidate,
                          const std::string& heat_map_path);

}  // namespace lumen::differential

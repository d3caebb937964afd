// The pixels behind an image pattern (image_map, bump_map, material_map, image_pattern): the
// image as POV-Ray stores it once read (image/pov_storage.hpp), with the filter and transmit
// of each palette entry. The kinds that use it and their settings: scene/pattern_kinds.hpp.
#pragma once
#include <array>
#include <vector>

#include "image/pov_storage.hpp"

namespace lumen::scene {

struct ImageData {
    image::PovImage image;
    // Palette images: filter and transmit per entry. Transmit starts as 1 - alpha; `filter all`
    // and `transmit all` overwrite every entry, `filter N, F` and `transmit N, T` one.
    std::vector<std::array<float, 2>> entry_filter_transmit;
    // Whether some colour looked up has filter or transmit (alpha, `once` outside the image,
    // filter or transmit given): shadow rays must then look at the pigment.
    bool may_pass_light = false;
};

}  // namespace lumen::scene

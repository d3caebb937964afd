// The file part of every image block (height_field, image_map, bump_map, material_map,
// image_pattern): `[TYPE] "file" [gamma G | gamma srgb] [premultiplied B]`, the file found on
// the search path and read (image/image_file.hpp).
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "image/image_file.hpp"
#include "image/pov_storage.hpp"
#include "interp/item_cursor.hpp"

namespace lumen::interp {

struct ImageName {
    image::Format format;
    std::string name;  // as written
    SourceLoc loc;     // of the name: where errors about the file point
};

// `[TYPE] "file"`: the type keyword, or the name's extension; a name without one is a PNG
// (POV-Ray's default output type). `block` names the block in messages.
ImageName read_image_name(ItemCursor& cur, std::string_view block);

// `gamma G` / `gamma srgb` and `premultiplied B` after the name: the decoding the scene asks
// for, if it gives one (premultiplied alpha is read and ignored).
std::optional<image::Decode> read_image_gamma(ItemCursor& cur);

struct LoadedImage {
    image::ImageFile file;
    std::string path;  // where it was found
};
// Finds and reads the file, or fails at the name with the reason.
LoadedImage load_image(ItemCursor& cur, const ImageName& name);

}  // namespace lumen::interp

// Image type keywords and extensions, and the dispatch to each family's reader.
#include "image/image_file.hpp"

#include <algorithm>
#include <cctype>

namespace lumen::image {

namespace {

struct FormatName {
    Format format;
    const char* keyword;
};
constexpr FormatName kKeywords[] = {
    {Format::Gif, "gif"},   {Format::Tga, "tga"},   {Format::Iff, "iff"},
    {Format::Ppm, "ppm"},   {Format::Pgm, "pgm"},   {Format::Png, "png"},
    {Format::Jpeg, "jpeg"}, {Format::Tiff, "tiff"}, {Format::Bmp, "bmp"},
    {Format::Exr, "exr"},   {Format::Hdr, "hdr"},   {Format::Sys, "sys"},
    {Format::Pot, "pot"}};

constexpr FormatName kExtensions[] = {
    {Format::Tga, "tga"},  {Format::Png, "png"},  {Format::Ppm, "ppm"},  {Format::Pgm, "pgm"},
    {Format::Gif, "gif"},  {Format::Iff, "iff"},  {Format::Jpeg, "jpg"}, {Format::Jpeg, "jpeg"},
    {Format::Tiff, "tif"}, {Format::Tiff, "tiff"}, {Format::Bmp, "bmp"}, {Format::Exr, "exr"},
    {Format::Hdr, "hdr"}};

}  // namespace

std::optional<Format> format_from_keyword(std::string_view word) {
    for (const FormatName& f : kKeywords)
        if (word == f.keyword) return f.format;
    return std::nullopt;
}

std::optional<Format> format_from_extension(std::string_view path) {
    const size_t dot = path.rfind('.');
    if (dot == std::string_view::npos || path.find('/', dot) != std::string_view::npos)
        return std::nullopt;
    const std::string_view ext = path.substr(dot + 1);
    const bool lower = std::none_of(ext.begin(), ext.end(), [](char c) { return std::isupper(uint8_t(c)); });
    const bool upper = std::none_of(ext.begin(), ext.end(), [](char c) { return std::islower(uint8_t(c)); });
    if (!lower && !upper) return std::nullopt;  // POV-Ray takes .png and .PNG, not .Png
    std::string folded(ext);
    for (char& c : folded) c = char(std::tolower(uint8_t(c)));
    for (const FormatName& f : kExtensions)
        if (folded == f.keyword) return f.format;
    return std::nullopt;
}

const char* format_keyword(Format f) {
    for (const FormatName& n : kKeywords)
        if (n.format == f) return n.keyword;
    return "?";
}

void check_image_size(long long width, long long height) {
    if (width <= 0 || height <= 0) throw ImageError("the image has no pixels");
    if (width > kMaxImageSide || height > kMaxImageSide ||
        size_t(width) * size_t(height) > kMaxImagePixels)
        throw ImageError("the image is too large (" + std::to_string(width) + " x " +
                         std::to_string(height) + " pixels)");
}

ImageFile read_image(const std::string& path, Format format) {
    switch (format) {
        case Format::Png: return read_png(path);
        case Format::Ppm:
        case Format::Pgm: return read_pnm(path);
        case Format::Tga: return read_tga(path);
        case Format::Gif: return read_gif(path);
        case Format::Pot: return read_pot(path);
        case Format::Jpeg: return read_jpeg(path);
        case Format::Tiff:
        case Format::Bmp:
        case Format::Exr:
        case Format::Hdr: return read_with_oiio(path);
        case Format::Iff: throw ImageError("IFF images are not supported");
        case Format::Sys: break;
    }
    throw ImageError("'sys' images cannot be read on this system");
}

}  // namespace lumen::image

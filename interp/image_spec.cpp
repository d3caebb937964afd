#include "interp/image_spec.hpp"

#include "base/file_resolver.hpp"
#include "interp/builders.hpp"

namespace lumen::interp {

ImageName read_image_name(ItemCursor& cur, std::string_view block) {
    std::optional<image::Format> format;
    SourceLoc loc = cur.next_loc();
    if (!cur.at_end() && cur.peek().kind == Item::Kind::Keyword) {
        format = image::format_from_keyword(cur.peek().keyword);
        if (format) cur.next();
    }
    if (format && !cur.at_end()) loc = cur.peek().loc;  // errors point at the file name
    const std::string name = cur.expect_string(format ? image::format_keyword(*format) : block);
    if (!format) {
        format = image::format_from_extension(name);
        if (!format && name.find('.') == std::string::npos) format = image::Format::Png;  // the +F default
        if (!format) cur.fail(loc, "cannot tell the image type of '" + name + "' from its extension");
    }
    return {*format, name, loc};
}

std::optional<image::Decode> read_image_gamma(ItemCursor& cur) {
    std::optional<image::Decode> decode;
    for (;;) {
        if (cur.accept_keyword("gamma")) {
            if (cur.accept_keyword("srgb")) {
                decode = image::Decode{image::Decode::Kind::SRGB, 1};
                continue;
            }
            const SourceLoc loc = cur.next_loc();
            const double g = cur.expect_float("gamma");
            if (!(g > 0)) cur.fail(loc, "the image gamma must be positive");
            decode = image::Decode{image::Decode::Kind::Power, g};
        } else if (cur.accept_keyword("premultiplied")) {
            cur.optional_bool();
        } else {
            return decode;
        }
    }
}

LoadedImage load_image(ItemCursor& cur, const ImageName& name) {
    LoadedImage out;
    out.path = FileResolver(cur.ctx().search_path).find(name.name, FileResolver::Kind::Image);
    if (out.path.empty()) cur.fail(name.loc, "cannot find image file '" + name.name + "'");
    try {
        out.file = image::read_image(out.path, name.format);
    } catch (const image::ImageError& e) {
        cur.fail(name.loc, "cannot read image '" + name.name + "': " + e.what());
    }
    return out;
}

}  // namespace lumen::interp

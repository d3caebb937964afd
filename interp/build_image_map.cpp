// image_map { FILE [once] [map_type N] [interpolate N] [filter|transmit all V | N, V]
//             [use_color | use_index] }, bump_map { FILE ... [use_index] [bump_size A] },
// image_pattern { FILE ... [use_alpha] }, material_map { FILE ... texture {} ... }: the image
// read now (interp/image_spec.hpp) and stored as POV-Ray stores it for that use.
#include <algorithm>
#include <sstream>

#include "interp/build_common.hpp"
#include "interp/image_spec.hpp"
#include "scene/image_map.hpp"

namespace lumen::interp {

namespace {

enum class Use { Colour, Pattern, Bump, Material };

struct ImageBlock {
    Use use;
    const char* keyword;
    const char* owner;  // the only block it may stand in; "" = any pattern owner
};
constexpr ImageBlock kImageBlocks[] = {
    {Use::Colour, "image_map", "pigment"},
    {Use::Pattern, "image_pattern", ""},
    {Use::Bump, "bump_map", "normal"},
    {Use::Material, "material_map", "texture"},
};

// Only image_map decodes the file's gamma: the 3.7 defaults of image/pov_storage.hpp, then
// encoded for a working gamma other than 1. A scene before #version 3.7 decodes only what the
// file's own sRGB or gAMA chunk says, and only with an assumed_gamma; without one, nothing.
// The other uses take the stored levels unless the scene gives a gamma.
image::Decode decoding(const BuildContext& ctx, Use use, const image::ImageFile& file,
                       image::Format format, const std::optional<image::Decode>& given) {
    if (use != Use::Colour) return given.value_or(image::Decode{});
    image::Decode d;
    if (given) {
        d = *given;
    } else if (ctx.language_version >= 3.7) {
        d = image::default_decode(file, format);
    } else if (!ctx.assumed_gamma) {
        return {};
    } else if (const auto chunk = image::file_decode(file)) {
        d = *chunk;
    } else {
        return {};  // the file's gamma is taken to be the working gamma
    }
    d.working_gamma = ctx.assumed_gamma.value_or(1.0);
    return d;
}

// `filter all F`, `filter N, F` (and transmit likewise).
void read_filter_or_transmit(ItemCursor& cur, const Item& kw, scene::pattern::ImageSource& k,
                             scene::ImageData& data) {
    const bool transmit = kw.keyword == "transmit";
    const int channel = transmit ? 1 : 0;
    const image::PovImage& img = data.image;
    if (cur.accept_keyword("all")) {
        const float v = float(cur.expect_float(kw.keyword));
        if (img.palette) {
            for (auto& e : data.entry_filter_transmit) e[channel] = v;
        } else {
            (transmit ? k.transmit : k.filter) = v;
        }
        if (v != 0) data.may_pass_light = true;
        return;
    }
    const SourceLoc loc = cur.next_loc();
    const double n = cur.expect_float(kw.keyword);
    const float v = float(cur.expect_float(kw.keyword));
    if (!img.palette)
        cur.fail(kw.loc, "'" + kw.keyword + " N, V' sets a palette entry, and this image has no palette",
                 "use '" + kw.keyword + " all V'");
    const size_t entries = data.entry_filter_transmit.size();
    // POV-Ray's rounding of the entry number, int(n + 0.01), checked before it is converted.
    if (!(n + 0.01 >= 0 && n + 0.01 < double(entries))) {
        std::ostringstream number;
        number << n;
        cur.fail(loc, "palette entry " + number.str() + " is not in the image's " +
                          std::to_string(entries) + " entries");
    }
    const int index = int(n + 0.01);
    data.entry_filter_transmit[size_t(index)][channel] = v;
    if (v != 0) data.may_pass_light = true;
    k.entry_changes.insert(k.entry_changes.end(), {double(channel), double(index), double(v)});
}

// POV-Ray accepts only these in an image_map; the other image blocks take any integer.
void check_choice(ItemCursor& cur, SourceLoc loc, Use use, const char* what, int v,
                  std::initializer_list<int> allowed) {
    if (use != Use::Colour || std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return;
    std::string list;
    for (int a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
    cur.fail(loc, std::string("an image_map's ") + what + " must be one of " + list);
}

// The modifiers after the file, into k; material_map's textures into `textures`.
void read_modifiers(ItemCursor& cur, Use use, scene::pattern::ImageSource& k,
                    scene::ImageData& data, scene::pattern::BumpMap* bump,
                    std::vector<scene::LayeredTexture>* textures) {
    static const std::vector<std::string> words = {
        "once", "map_type", "interpolate", "use_color", "use_colour", "use_index", "use_alpha",
        "filter", "transmit", "bump_size", "texture"};
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (textures && item.kind == Item::Kind::Value &&
            item.value.is<std::shared_ptr<const TextureValue>>()) {
            textures->push_back(item.value.as<std::shared_ptr<const TextureValue>>()->layers);
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, words);
        const std::string& w = item.keyword;
        if (w == "once") {
            k.once = true;
            data.may_pass_light = data.may_pass_light || use == Use::Colour;  // transparent off the map
        } else if (w == "map_type") {
            const SourceLoc loc = cur.next_loc();
            k.map_type = cur.expect_int(w);
            check_choice(cur, loc, use, "map_type", k.map_type, {0, 1, 2, 5});
        } else if (w == "interpolate") {
            const SourceLoc loc = cur.next_loc();
            k.interpolate = cur.expect_int(w);
            check_choice(cur, loc, use, "interpolate", k.interpolate, {2, 3, 4});
        } else if (w == "use_color" || w == "use_colour") {
            k.use_index = false;
        } else if (w == "use_index") {
            k.use_index = true;
        } else if (w == "use_alpha" && use == Use::Pattern) {
            k.use_alpha = true;
        } else if ((w == "filter" || w == "transmit") && use == Use::Colour) {
            read_filter_or_transmit(cur, item, k, data);
        } else if (w == "bump_size" && bump) {
            bump->bump_size = double(float(cur.expect_float(w)));
            bump->bump_size_given = true;
        } else {
            cur.fail_unexpected(item, words);
        }
    }
}

std::shared_ptr<scene::ImageData> stored(const image::ImageFile& file, image::Format format,
                                         const image::Decode& decode) {
    auto data = std::make_shared<scene::ImageData>();
    data->image = image::store_as_pov(file, format, decode);
    const image::PovImage& img = data->image;
    for (const auto& c : img.colours)
        if (c[3] < 1) data->may_pass_light = true;
    if (img.palette)
        for (const auto& c : img.colours) data->entry_filter_transmit.push_back({0.0f, 1.0f - c[3]});
    return data;
}

// Reads the block into a kind of type K.
template <class K>
K read_image(ItemCursor& cur, Use use, std::vector<scene::LayeredTexture>* textures) {
    const char* keyword = kImageBlocks[int(use)].keyword;
    const ImageName name = read_image_name(cur, keyword);
    if (name.format == image::Format::Pot || name.format == image::Format::Iff || name.format == image::Format::Sys)
        cur.fail(name.loc, std::string(image::format_keyword(name.format)) + " images cannot make an " + keyword);
    const std::optional<image::Decode> given = read_image_gamma(cur);
    LoadedImage loaded = load_image(cur, name);
    K k;
    k.file = loaded.path;
    auto data = stored(loaded.file, name.format, decoding(cur.ctx(), use, loaded.file, name.format, given));
    scene::pattern::BumpMap* bump = nullptr;
    if constexpr (std::is_same_v<K, scene::pattern::BumpMap>) bump = &k;
    read_modifiers(cur, use, k, *data, bump, textures);
    k.data = std::move(data);
    return k;
}

}  // namespace

bool read_image_block(ItemCursor& cur, const Item& kw, scene::Pattern& pattern,
                      const std::string& owner, std::vector<scene::LayeredTexture>* textures) {
    const ImageBlock* block = nullptr;
    const BlockValue* body = nullptr;
    for (const ImageBlock& b : kImageBlocks)
        if ((body = block_of(kw, b.keyword))) {
            block = &b;
            break;
        }
    if (!block) return false;
    if (*block->owner && owner != block->owner)
        cur.fail(kw.loc, std::string(block->keyword[0] == 'i' ? "an " : "a ") + block->keyword + " belongs in a " + block->owner +
                             (owner.empty() ? "" : ", not a " + owner),
                 block->use == Use::Colour ? "use image_pattern for an image's grey as a pattern value" : "");
    ItemCursor sub(cur.ctx(), *body);
    switch (block->use) {
        case Use::Colour: pattern.kind = read_image<scene::pattern::ImageMap>(sub, block->use, nullptr); break;
        case Use::Pattern: pattern.kind = read_image<scene::pattern::ImagePattern>(sub, block->use, nullptr); break;
        case Use::Bump: pattern.kind = read_image<scene::pattern::BumpMap>(sub, block->use, nullptr); break;
        case Use::Material: {
            std::vector<scene::LayeredTexture> list;
            auto k = read_image<scene::pattern::MaterialMap>(sub, block->use, &list);
            if (list.empty()) cur.fail(kw.loc, "a material_map needs at least one texture");
            k.textures = int(list.size());
            pattern.kind = std::move(k);
            if (textures) *textures = std::move(list);
            break;
        }
    }
    pattern.frequency = 0;  // the image's value as it is: no wave
    pattern.wave = scene::WaveType::Ramp;
    return true;
}

}  // namespace lumen::interp

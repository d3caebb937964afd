// height_field { [TYPE] "file" [gamma G | gamma srgb] [premultiplied B] [water_level w]
// [smooth] [hierarchy B] OBJECT_MODIFIERS }: the image read now (image/image_file.hpp) and
// turned into POV-Ray's 16-bit heights; or `function W, H { expr }`, an image made by
// evaluating a float expression (pigment functions are not supported).
#include <algorithm>
#include <cmath>

#include "image/image_file.hpp"
#include "image/pov_storage.hpp"
#include "interp/build_common.hpp"
#include "interp/image_spec.hpp"
#include "parser/ast.hpp"

namespace lumen::interp {

namespace {

// POV-Ray's height of one stored pixel: a palette index times 256; grey (including the
// requantised 8-bit grey) and colours of more than 8 bits as trunc(grey * 65535); an 8-bit
// colour as red the high byte and green the low byte, trunc((r * 256 + g) * 255). In single
// precision: 16-bit level k gives k again (measured for k = 1, 2, 3), where the product in
// double drops half of the levels by one.
uint16_t pixel_height(const image::PovImage& img, int column, int row) {
    const size_t i = size_t(row) * size_t(img.width) + size_t(column);
    if (img.palette) return uint16_t(img.indices[i] * 256);
    const std::array<float, 4>& c = img.colours[i];
    auto clamped = [](float v) { return uint16_t(std::trunc(std::clamp(v, 0.0f, 65535.0f))); };
    if (img.grey) return clamped(c[0] * 65535.0f);
    if (img.high_precision) return clamped(image::pov_grey(c[0], c[1], c[2]) * 65535.0f);
    return clamped(float((double(c[0]) * 256.0 + double(c[1])) * 255.0));
}

// The heights as the grid holds them: Map[z][x] = height(column x, row iH - 1 - z), so the
// image's bottom row lies at z = 0.
std::vector<uint16_t> grid_of(const image::PovImage& img) {
    std::vector<uint16_t> heights(size_t(img.width) * size_t(img.height));
    for (int z = 0; z < img.height; ++z)
        for (int x = 0; x < img.width; ++x)
            heights[size_t(z) * size_t(img.width) + size_t(x)] = pixel_height(img, x, img.height - 1 - z);
    return heights;
}

uint64_t hash_heights(const std::vector<uint16_t>& h) {
    uint64_t v = 1469598103934665603ULL;  // FNV-1a over the little-endian values
    for (uint16_t x : h) {
        v = (v ^ (x & 0xff)) * 1099511628211ULL;
        v = (v ^ (x >> 8)) * 1099511628211ULL;
    }
    return v;
}

// The field of a stored image, with its options and the object modifiers that follow.
scene::ObjectPtr field_object(ItemCursor& cur, SourceLoc block, const image::PovImage& img) {
    scene::HeightField hf;
    hf.columns = img.width;
    hf.rows = img.height;
    auto heights = std::make_shared<std::vector<uint16_t>>(grid_of(img));
    hf.heights_hash = hash_heights(*heights);
    hf.heights = std::move(heights);
    for (;;) {
        if (cur.accept_keyword("water_level")) {
            hf.water_level = cur.expect_float("water_level");
            if (cur.ctx().language_version < 2.0) hf.water_level /= 256;  // POV-Ray 1's 0..256
        } else if (cur.accept_keyword("smooth")) {
            hf.smooth = true;
        } else if (cur.accept_keyword("hierarchy")) {
            hf.hierarchy = cur.optional_bool();
        } else {
            break;
        }
    }
    scene::Object obj;
    obj.loc = block;
    obj.shape = std::move(hf);
    read_object_modifiers(cur, obj, [](const Item&) { return false; }, {});
    return std::make_shared<scene::Object>(std::move(obj));
}

// `function W, H { expr }`: a W x H image whose pixel (column j, row i from the top) is
// expr at (j / (W - 1), i / (H - 1), 0), stored as 16-bit grey trunc(v * 65535) with v kept
// in [0, 1]; a pigment function's as 16-bit colour channels. Null when the function cannot be
// evaluated here (a spline function, or a pigment without the renderer's host).
std::shared_ptr<image::PovImage> function_image(ItemCursor& cur, const FunctionValue& fn) {
    const ast::Node& node = *fn.node;
    if (!node.flag || node.children.size() != 3 || !cur.ctx().eval_at) return nullptr;
    if (!fn.program || (fn.program->needs_host && !cur.ctx().function_host)) return nullptr;
    if (fn.program->params > 3)
        cur.fail(node.loc, "a height_field function is given x, y and z: this one takes " +
                               std::to_string(fn.program->params) + " parameters");
    const bool colour = fn.program->components > 1;
    auto size = [&](const ast::Node& e) {
        const double v = cur.ctx().eval_at(e, 0, 0, 0);
        if (!(v + 0.5 >= 2 && v + 0.5 < image::kMaxImageSide + 1))
            cur.fail(e.loc, "a function image needs 2 to " + std::to_string(image::kMaxImageSide) +
                                " pixels a side");
        return int(v + 0.5);
    };
    const int w = size(*node.children[0]), h = size(*node.children[1]);
    if (size_t(w) * size_t(h) > image::kMaxImagePixels)
        cur.fail(node.loc, "the function image is too large");
    auto img = std::make_shared<image::PovImage>();
    img->width = w;
    img->height = h;
    img->grey = !colour;
    img->high_precision = true;
    img->colours.resize(size_t(w) * size_t(h));
    const fn::Context context = cur.ctx().function_context();
    auto channel = [](double v) {
        return float(std::trunc(std::clamp(std::isnan(v) ? 0.0 : v, 0.0, 1.0) * 65535) / 65535);
    };
    for (int i = 0; i < h; ++i)
        for (int j = 0; j < w; ++j) {
            const double p[3] = {double(j) / (w - 1), double(i) / (h - 1), 0};
            auto& px = img->colours[size_t(i) * size_t(w) + size_t(j)];
            if (!colour) {
                const float g = channel(fn::evaluate(*fn.program, p, context));
                px = {g, g, g, 1};
                continue;
            }
            for (int c = 0; c < 3; ++c) px[c] = channel(fn::evaluate(*fn.program, p, context, c));
            px[3] = 1;
        }
    return img;
}

}  // namespace

scene::ObjectPtr build_height_field(ItemCursor& cur) {
    const SourceLoc block = cur.block_loc();
    if (cur.next_is<std::shared_ptr<const FunctionValue>>()) {
        const auto& fn = *cur.next().value.as<std::shared_ptr<const FunctionValue>>();
        auto img = function_image(cur, fn);
        if (!img) return unsupported_object({"height_field function", block});
        return field_object(cur, block, *img);
    }
    if (cur.next_is_vector_like()) {  // POV-Ray 1's leading vector
        cur.warn(cur.peek().loc, "the vector before a height_field's image is ignored");
        cur.expect_vecn("");
    }
    const ImageName name = read_image_name(cur, "height_field");
    if (name.format == image::Format::Iff) cur.fail(name.loc, "iff images cannot make a height_field");
    // Height fields use the raw values unless a gamma is given.
    const image::Decode decode = read_image_gamma(cur).value_or(image::Decode{});
    const image::ImageFile file = load_image(cur, name).file;
    if (file.width < 2 || file.height < 2)
        cur.fail(name.loc, "a height_field image needs at least 2 x 2 pixels");
    return field_object(cur, block, image::store_as_pov(file, name.format, decode));
}

}  // namespace lumen::interp

// lumen merge on files made here: every type lumen writes, 8 and 16 bits, alpha, gamma labels.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "base/diagnostics.hpp"
#include "cli/merge.hpp"
#include "render/image_output.hpp"

namespace lumen::cli {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    return fs::temp_directory_path() / ("lumen_merge_" + std::to_string(getpid()) + "_" + name);
}

std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// A test picture and the part of it in rows [top, bottom) (zero elsewhere).
render::EncodedImage picture(int channels, int maxval, int top = 0, int bottom = 9) {
    render::EncodedImage e;
    e.width = 7;
    e.height = 9;
    e.channels = channels;
    e.maxval = maxval;
    e.curve = render::EncodedImage::Curve::Power;
    e.file_gamma = 2.2;
    e.values.resize(size_t(e.width) * e.height * channels);
    for (size_t i = 0; i < e.values.size(); ++i) {
        const int y = int(i / (size_t(e.width) * channels));
        const float v = maxval ? float((i * 37) % size_t(maxval + 1)) : float(i) * 0.01f;
        e.values[i] = y >= top && y < bottom ? v : 0.0f;
    }
    return e;
}

struct Case {
    render::FileType type;
    const char* ext;
    int channels, maxval;
};

TEST(Merge, RowBandsGiveTheWholeFileInEveryType) {
    for (const Case c : {Case{render::FileType::PNG, ".png", 3, 255}, Case{render::FileType::PNG, ".png", 4, 65535},
                         Case{render::FileType::PPM, ".ppm", 3, 255}, Case{render::FileType::PPM, ".ppm", 3, 65535},
                         Case{render::FileType::EXR, ".exr", 4, 0}}) {
        const fs::path whole = scratch(std::string("whole") + c.ext);
        const fs::path top = scratch(std::string("top") + c.ext), rest = scratch(std::string("rest") + c.ext);
        const fs::path merged = scratch(std::string("merged") + c.ext);
        render::write_encoded(picture(c.channels, c.maxval), c.type, whole.string());
        render::write_encoded(picture(c.channels, c.maxval, 0, 4), c.type, top.string());
        render::write_encoded(picture(c.channels, c.maxval, 4, 9), c.type, rest.string());
        const MergeResult r = merge_parts({{top.string()}, {rest.string()}}, merged.string());
        EXPECT_EQ(r.width, 7);
        EXPECT_EQ(r.blank, 0u);
        EXPECT_EQ(bytes_of(merged), bytes_of(whole)) << c.ext << " " << c.maxval;
        for (const fs::path& p : {whole, top, rest, merged}) fs::remove(p);
    }
}

// Cropped parts (Output_Crop) placed by position give the same file.
TEST(Merge, CroppedPartsArePlacedWhereTheyBelong) {
    const render::EncodedImage full = picture(3, 255);
    auto crop = [&](int x0, int y0, int w, int h) {
        render::EncodedImage c = full;
        c.width = w;
        c.height = h;
        c.values.clear();
        for (int y = y0; y < y0 + h; ++y)
            for (int x = x0; x < x0 + w; ++x)
                for (int k = 0; k < 3; ++k) c.values.push_back(full.values[size_t((y * 7 + x) * 3 + k)]);
        return c;
    };
    const fs::path whole = scratch("cwhole.png"), merged = scratch("cmerged.png");
    const fs::path left = scratch("cleft.png"), right = scratch("cright.png");
    render::write_encoded(full, render::FileType::PNG, whole.string());
    render::write_encoded(crop(0, 0, 4, 9), render::FileType::PNG, left.string());
    render::write_encoded(crop(4, 0, 3, 9), render::FileType::PNG, right.string());
    merge_parts({{left.string(), 0, 0}, {right.string(), 4, 0}}, merged.string(), 7, 9);
    EXPECT_EQ(bytes_of(merged), bytes_of(whole));
    for (const fs::path& p : {whole, merged, left, right}) fs::remove(p);
}

TEST(Merge, RefusesPartsThatDoNotBelongTogether) {
    const fs::path a = scratch("a.png"), b = scratch("b.png"), out = scratch("out.png");
    render::write_encoded(picture(3, 255, 0, 5), render::FileType::PNG, a.string());
    render::EncodedImage other = picture(3, 255, 3, 9);
    other.values[size_t(3 * 7 * 3 + 4)] += 1;  // row 3: rendered by both, differently
    render::write_encoded(other, render::FileType::PNG, b.string());
    EXPECT_THROW(merge_parts({{a.string()}, {b.string()}}, out.string()), LumenError);
    render::write_encoded(picture(4, 255, 5, 9), render::FileType::PNG, b.string());  // alpha
    EXPECT_THROW(merge_parts({{a.string()}, {b.string()}}, out.string()), LumenError);
    EXPECT_THROW(merge_parts({{a.string()}, {scratch("missing.png").string()}}, out.string()), LumenError);
    EXPECT_THROW(merge_parts({{a.string()}}, scratch("out.jpg").string()), LumenError);
    EXPECT_THROW(merge_parts({{a.string(), 1, 0}}, out.string(), 7, 9), LumenError);  // does not fit
    EXPECT_FALSE(fs::exists(out));
    fs::remove(a);
    fs::remove(b);
}

}  // namespace
}  // namespace lumen::cli

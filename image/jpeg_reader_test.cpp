// The JPEG reader against the OpenImageIO module it replaces: the same samples for a colour
// file (the corpus's slopemt height field) and a greyscale one written here, and errors for a
// damaged file.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <jpeglib.h>

#include <gtest/gtest.h>

#include "image/image_file.hpp"

namespace lumen::image {
namespace {

namespace fs = std::filesystem;

const fs::path kColourJpeg = "/usr/share/povray-3.7/scenes/textures/patterns/slopemt_dat_36.jpg";

fs::path temp_file(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / "lumen_jpeg_tests";
    fs::create_directories(dir);
    return dir / name;
}

// A 37 x 23 greyscale JPEG of a diagonal ramp with some noise, at quality 80.
fs::path write_grey_jpeg() {
    const fs::path path = temp_file("grey.jpg");
    std::FILE* f = std::fopen(path.c_str(), "wb");
    jpeg_compress_struct info{};
    jpeg_error_mgr err{};
    info.err = jpeg_std_error(&err);
    jpeg_create_compress(&info);
    jpeg_stdio_dest(&info, f);
    info.image_width = 37;
    info.image_height = 23;
    info.input_components = 1;
    info.in_color_space = JCS_GRAYSCALE;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, 80, TRUE);
    jpeg_start_compress(&info, TRUE);
    std::vector<JSAMPLE> row(37);
    unsigned seed = 7;
    while (info.next_scanline < info.image_height) {
        for (int x = 0; x < 37; ++x) {
            seed = seed * 1103515245 + 12345;
            row[x] = JSAMPLE((x * 5 + info.next_scanline * 7 + (seed >> 28)) & 255);
        }
        JSAMPROW r = row.data();
        jpeg_write_scanlines(&info, &r, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::fclose(f);
    return path;
}

void expect_same(const ImageFile& a, const ImageFile& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels, b.channels);
    EXPECT_EQ(a.bit_depth, b.bit_depth);
    EXPECT_EQ(a.floating, b.floating);
    ASSERT_EQ(a.values.size(), b.values.size());
    size_t differ = 0;
    for (size_t i = 0; i < a.values.size(); ++i) differ += a.values[i] != b.values[i];
    EXPECT_EQ(differ, 0u);
}

TEST(JpegReader, SamplesAreOpenImageIOs) {
    ASSERT_TRUE(fs::exists(kColourJpeg)) << "povray-examples is missing: tools/install-deps.sh";
    const ImageFile colour = read_image(kColourJpeg, Format::Jpeg);
    EXPECT_EQ(colour.width, 160);
    EXPECT_EQ(colour.channels, 3);
    expect_same(colour, read_with_oiio(kColourJpeg));
    const fs::path grey_path = write_grey_jpeg();
    const ImageFile grey = read_jpeg(grey_path);
    EXPECT_EQ(grey.channels, 1);
    EXPECT_EQ(grey.height, 23);
    expect_same(grey, read_with_oiio(grey_path));
}

TEST(JpegReader, DamagedFilesAreErrors) {
    std::ifstream in(kColourJpeg, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 1000u);
    const fs::path cut = temp_file("cut.jpg");
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, 300);  // the header, no scan
    EXPECT_THROW(read_jpeg(cut), ImageError);
    const fs::path junk = temp_file("junk.jpg");
    std::ofstream(junk, std::ios::binary) << "not a jpeg at all";
    EXPECT_THROW(read_jpeg(junk), ImageError);
    EXPECT_THROW(read_jpeg(temp_file("missing.jpg")), ImageError);
}

}  // namespace
}  // namespace lumen::image

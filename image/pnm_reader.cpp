// Netpbm images: P2/P5 (PGM, grey) and P3/P6 (PPM, RGB), ASCII or binary, any maxval up to
// 65535. As POV-Ray does, levels are brought to 8 bits (maxval <= 255: k * 255 / maxval) or
// 16 bits (k * 65535 / maxval) before they become values.
#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>

#include "image/image_file.hpp"

namespace lumen::image {

namespace {

class Scanner {
public:
    explicit Scanner(const std::string& bytes) : s_(bytes) {}

    // The next decimal number of the header or of ASCII data, skipping blanks and # comments.
    long long number() {
        for (;;) {
            while (pos_ < s_.size() && std::isspace(uint8_t(s_[pos_]))) ++pos_;
            if (pos_ < s_.size() && s_[pos_] == '#') {
                while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
                continue;
            }
            break;
        }
        if (pos_ >= s_.size() || !std::isdigit(uint8_t(s_[pos_])))
            throw ImageError("corrupt PPM/PGM data: a number was expected");
        long long v = 0;
        while (pos_ < s_.size() && std::isdigit(uint8_t(s_[pos_]))) {
            v = v * 10 + (s_[pos_++] - '0');
            if (v > (1 << 30)) throw ImageError("corrupt PPM/PGM data: a number is too large");
        }
        return v;
    }
    // Binary data starts after exactly one blank following maxval.
    void skip_one_blank() {
        if (pos_ >= s_.size() || !std::isspace(uint8_t(s_[pos_])))
            throw ImageError("corrupt PPM/PGM header");
        ++pos_;
    }
    unsigned byte() {
        if (pos_ >= s_.size()) throw ImageError("the PPM/PGM file is truncated");
        return uint8_t(s_[pos_++]);
    }

private:
    const std::string& s_;
    size_t pos_ = 0;
};

}  // namespace

ImageFile read_pnm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ImageError("cannot open the file");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < 2 || bytes[0] != 'P' || bytes[1] == 0 ||
        !std::strchr("2356", bytes[1]))
        throw ImageError("not a PPM/PGM file (P2, P3, P5 or P6)");
    const char kind = bytes[1];
    Scanner scan(bytes);
    scan.byte(), scan.byte();
    const long long width = scan.number(), height = scan.number();
    check_image_size(width, height);
    const long long maxval = scan.number();
    if (maxval < 1 || maxval > 65535) throw ImageError("PPM/PGM maxval must be 1 to 65535");
    const bool ascii = kind == '2' || kind == '3';
    if (!ascii) scan.skip_one_blank();

    ImageFile img;
    img.width = int(width);
    img.height = int(height);
    img.channels = kind == '2' || kind == '5' ? 1 : 3;
    const bool wide = maxval > 255;
    img.bit_depth = wide ? 16 : 8;
    const long long full = wide ? 65535 : 255;
    const size_t n = img.pixels() * size_t(img.channels);
    if (!ascii && bytes.size() < n * (wide ? 2 : 1)) throw ImageError("the PPM/PGM file is truncated");
    img.values.resize(n);
    for (size_t i = 0; i < n; ++i) {
        long long k;
        if (ascii) k = scan.number();
        else if (wide) {
            const unsigned high = scan.byte();
            k = (high << 8) | scan.byte();
        }
        else k = scan.byte();
        if (k > maxval) k = maxval;
        img.values[i] = float(k * full / maxval) / float(full);
    }
    return img;
}

}  // namespace lumen::image

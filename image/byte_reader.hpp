// A whole little-endian file in memory, read byte by byte; reading past its end is an
// ImageError naming the format ("the TGA file is truncated").
#pragma once
#include <fstream>
#include <iterator>
#include <string>

#include "image/image_file.hpp"

namespace lumen::image {

class ByteReader {
public:
    // The file at `path` (an ImageError if it cannot be opened); `format` names it in errors.
    ByteReader(const std::string& path, const char* format) : format_(format) {
        std::ifstream file(path, std::ios::binary);
        if (!file) throw ImageError("cannot open the file");
        s_.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    }
    unsigned u8() {
        if (pos_ >= s_.size()) truncated();
        return uint8_t(s_[pos_++]);
    }
    unsigned u16() {
        const unsigned lo = u8();
        return lo | (u8() << 8);
    }
    void skip(size_t n) {
        if (s_.size() - pos_ < n) truncated();
        pos_ += n;
    }
    // The next n bytes appended to `out`.
    void take(size_t n, std::string& out) {
        if (s_.size() - pos_ < n) truncated();
        out.append(s_, pos_, n);
        pos_ += n;
    }
    size_t size() const { return s_.size(); }

private:
    [[noreturn]] void truncated() const {
        throw ImageError(std::string("the ") + format_ + " file is truncated");
    }
    std::string s_;
    size_t pos_ = 0;
    const char* format_;
};

}  // namespace lumen::image

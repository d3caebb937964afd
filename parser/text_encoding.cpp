#include "parser/text_encoding.hpp"

#include <cstdio>
#include <string_view>

#include "parser/parser.hpp"

namespace lumen::parser {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

// "UTF-16 LE", "UTF-32 BE", ... or null: by the byte order mark, or, without one, by the zero
// bytes that ASCII characters leave in every other byte.
const char* wide_encoding(std::string_view t) {
    using namespace std::string_view_literals;
    if (starts_with(t, "\xFF\xFE\0\0"sv)) return "UTF-32 LE";
    if (starts_with(t, "\0\0\xFE\xFF"sv)) return "UTF-32 BE";
    if (starts_with(t, "\xFF\xFE"sv)) return "UTF-16 LE";
    if (starts_with(t, "\xFE\xFF"sv)) return "UTF-16 BE";
    const size_t pairs = std::min<size_t>(t.size(), 4096) / 2;
    size_t zero_even = 0, zero_odd = 0;
    for (size_t i = 0; i < pairs; ++i) {
        zero_even += t[2 * i] == '\0';
        zero_odd += t[2 * i + 1] == '\0';
    }
    // Mostly ASCII text: nearly every high (or low) byte is zero, its partner nearly never.
    if (pairs > 0 && zero_odd * 10 >= pairs * 7 && zero_even * 10 <= pairs) return "UTF-16 LE";
    if (pairs > 0 && zero_even * 10 >= pairs * 7 && zero_odd * 10 <= pairs) return "UTF-16 BE";
    return nullptr;
}

// Bytes no SDL text holds: NUL and the control characters other than the white space ones
// and ^Z (which old DOS files end with, and the grammar skips).
bool is_binary_byte(unsigned char c) {
    return c < 0x20 && c != '\t' && c != '\n' && c != '\v' && c != '\f' && c != '\r' && c != 0x1A;
}

const char* known_format(std::string_view t) {
    using namespace std::string_view_literals;
    if (starts_with(t, "\x89PNG"sv)) return "a PNG image";
    if (starts_with(t, "\xFF\xD8\xFF"sv)) return "a JPEG image";
    if (starts_with(t, "GIF8"sv)) return "a GIF image";
    if (starts_with(t, "II*\0"sv) || starts_with(t, "MM\0*"sv)) return "a TIFF image";
    if (starts_with(t, "\x76\x2F\x31\x01"sv)) return "an OpenEXR image";
    if (starts_with(t, "\x1F\x8B"sv)) return "gzip data";
    if (starts_with(t, "PK\x03\x04"sv)) return "a zip archive";
    if (starts_with(t, "\x7F" "ELF"sv)) return "a program";
    return nullptr;
}

// Line and column (in bytes, as the grammar counts them) of byte `offset`.
SourceLoc location_of(const SourceFile& file, size_t offset) {
    uint32_t line = 1;
    size_t line_start = 0;
    for (size_t i = 0; i < offset; ++i)
        if (file.text[i] == '\n') ++line, line_start = i + 1;
    return SourceLoc{&file, line, uint32_t(offset - line_start + 1), uint32_t(offset)};
}

}  // namespace

void check_sdl_text(const SourceFile& file) {
    const std::string_view t = file.text;
    const SourceLoc start{&file, 1, 1, 0};
    if (const char* enc = wide_encoding(t))
        throw LumenError(start, "'" + file.name + "' is " + enc +
                                    " text: save it as UTF-8 (or ASCII) to use it as a scene file");
    // A NUL anywhere, or control bytes in quantity near the start (8 or more, over 1 % of the
    // first 4 KB), mark a binary file; a stray control byte in text is left to the grammar.
    size_t controls = 0, first = t.size();
    const size_t head = std::min<size_t>(t.size(), 4096);
    for (size_t i = 0; i < t.size(); ++i) {
        const auto c = static_cast<unsigned char>(t[i]);
        if (!is_binary_byte(c)) continue;
        if (first == t.size()) first = i;
        if (c == 0 || (i < head && ++controls >= 8 && controls * 100 > head)) {
            const char* format = known_format(t);
            char detail[64];
            std::snprintf(detail, sizeof detail, "byte 0x%02X at offset %zu",
                          unsigned(static_cast<unsigned char>(t[first])), first);
            throw LumenError(location_of(file, first), "'" + file.name + "' is a binary file" +
                                        (format ? std::string(" (") + format + ")" : std::string()) +
                                        ", not SDL text (" + detail + ")");
        }
    }
}

}  // namespace lumen::parser

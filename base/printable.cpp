// Escaping for terminal output (declared in diagnostics.hpp).
#include <cstdio>

#include "base/diagnostics.hpp"

namespace lumen {
namespace {

// Length of the valid UTF-8 sequence starting at s[i] (2..4 bytes), or 0 if there is none.
size_t utf8_sequence(std::string_view s, size_t i) {
    const auto b = [&](size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const unsigned char c = b(0);
    size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    for (size_t k = 1; k < n; ++k)
        if ((b(k) & 0xC0) != 0x80) return 0;
    // Overlong forms, UTF-16 surrogates, code points past U+10FFFF, and the C1 controls.
    if ((c == 0xE0 && b(1) < 0xA0) || (c == 0xED && b(1) > 0x9F) || (c == 0xF0 && b(1) < 0x90) ||
        (c == 0xF4 && b(1) > 0x8F) || (c == 0xC2 && b(1) < 0xA0))
        return 0;
    return n;
}

}  // namespace

std::string printable(std::string_view s, bool keep_newlines) {
    std::string out;
    out.reserve(s.size());
    for (size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        if ((c >= 0x20 && c < 0x7F) || c == '\t' || (keep_newlines && c == '\n')) {
            out += char(c);
            ++i;
        } else if (size_t n = c >= 0x80 ? utf8_sequence(s, i) : 0) {
            out.append(s.substr(i, n));
            i += n;
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", unsigned(c));
            out += buf;
            ++i;
        }
    }
    return out;
}

size_t display_width(std::string_view printable_text) {
    size_t n = 0;
    for (char c : printable_text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

}  // namespace lumen

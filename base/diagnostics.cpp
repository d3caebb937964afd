#include "base/diagnostics.hpp"

#include <algorithm>

namespace lumen {

namespace {

const char* severity_name(Severity s) {
    switch (s) {
        case Severity::Error: return "error";
        case Severity::Warning: return "warning";
        case Severity::Note: return "note";
    }
    return "error";
}

// Optimal-string-alignment distance: insertions, deletions, substitutions and swaps of two
// adjacent letters each cost 1, so "Rde" is one edit from "Red" and "Widht" from "Width".
size_t edit_distance(const std::string& a, const std::string& b) {
    const size_t n = a.size(), m = b.size();
    std::vector<size_t> d((n + 1) * (m + 1));
    auto at = [&](size_t i, size_t j) -> size_t& { return d[i * (m + 1) + j]; };
    for (size_t i = 0; i <= n; ++i) at(i, 0) = i;
    for (size_t j = 0; j <= m; ++j) at(0, j) = j;
    for (size_t i = 1; i <= n; ++i) {
        for (size_t j = 1; j <= m; ++j) {
            size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
        }
    }
    return at(n, m);
}

}  // namespace

std::string format_headline(const Diagnostic& d) {
    return printable(d.loc.str(), false) + ": " + severity_name(d.severity) + ": " +
           printable(d.message, true);
}

namespace {

// The source line under a headline, escaped, and a caret under column `column` (bytes). A
// line longer than the terminal (a binary file's) is cut to a window around the caret.
std::string source_excerpt(std::string_view line, uint32_t column) {
    constexpr size_t kWindow = 200;  // sample scenes have lines of 130 characters
    const size_t caret_byte = std::min<size_t>(column > 0 ? column - 1 : 0, line.size());
    std::string before = printable(line.substr(0, caret_byte), false);
    std::string after = printable(line.substr(caret_byte), false);
    std::string lead = "    ";
    if (display_width(before) > kWindow) {  // keep the last kWindow / 2 characters before it
        size_t keep = before.size(), chars = 0;
        while (keep > 0 && chars < kWindow / 2)
            chars += (static_cast<unsigned char>(before[--keep]) & 0xC0) != 0x80;
        before = before.substr(keep);
        lead += "...";
    }
    if (display_width(after) > kWindow) {
        size_t cut = 0, chars = 0;
        while (cut < after.size() && chars < kWindow)
            chars += (static_cast<unsigned char>(after[cut++]) & 0xC0) != 0x80;
        while (cut < after.size() && (static_cast<unsigned char>(after[cut]) & 0xC0) == 0x80) ++cut;
        after = after.substr(0, cut) + "...";
    }
    std::string out = lead + before + after + "\n" + std::string(lead.size(), ' ');
    // Keep tabs so the caret lines up under the same column.
    for (char c : before)
        if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) out += c == '\t' ? '\t' : ' ';
    return out + "^\n";
}

}  // namespace

std::string format_diagnostic(const Diagnostic& d) {
    std::string out = format_headline(d) + "\n";
    if (d.loc.file && d.loc.line > 0) {
        std::string_view line = d.loc.file->line_text(d.loc.line);
        if (!line.empty()) out += source_excerpt(line, d.loc.column);
    }
    if (!d.hint.empty()) out += printable(d.loc.str(), false) + ": note: " + printable(d.hint, false) + "\n";
    for (const SourceLoc& inc : d.include_chain)
        out += "in file included from " + printable(inc.str(), false) + "\n";
    return out;
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    size_t best_d = std::string::npos;
    for (const std::string& c : candidates) {
        size_t d = edit_distance(word, c);
        if (d < best_d) {
            best_d = d;
            best = c;
        }
    }
    // Allow about one edit per three characters, at least one.
    size_t limit = std::max<size_t>(1, word.size() / 3);
    if (best_d == 0 || best_d > limit) return {};
    return best;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
    std::string m = closest_match(word, candidates);
    return m.empty() ? std::string() : "did you mean '" + m + "'?";
}

}  // namespace lumen

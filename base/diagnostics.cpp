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
    return d.loc.str() + ": " + severity_name(d.severity) + ": " + d.message;
}

std::string format_diagnostic(const Diagnostic& d) {
    std::string out = format_headline(d) + "\n";
    if (d.loc.file && d.loc.line > 0) {
        std::string_view line = d.loc.file->line_text(d.loc.line);
        if (!line.empty()) {
            out += "    ";
            out += line;
            out += "\n    ";
            // Keep tabs so the caret lines up under the same column.
            for (uint32_t i = 1; i < d.loc.column && i - 1 < line.size(); ++i)
                out += line[i - 1] == '\t' ? '\t' : ' ';
            out += "^\n";
        }
    }
    if (!d.hint.empty()) out += d.loc.str() + ": note: " + d.hint + "\n";
    for (const SourceLoc& inc : d.include_chain)
        out += "in file included from " + inc.str() + "\n";
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

// Compiler-style diagnostics: `file:line:col: error: message`, the source line, a caret,
// an optional hint ("did you mean 'sphere'?") and the include chain.
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "base/source.hpp"

namespace lumen {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLoc loc;
    std::string message;
    std::string hint;                     // e.g. "did you mean 'sphere'?" (may be empty)
    std::vector<SourceLoc> include_chain;  // innermost first: where each file was included
};

// Thrown for any error that stops the run (parse, evaluation, render set-up).
struct LumenError : std::runtime_error {
    Diagnostic diag;
    explicit LumenError(Diagnostic d) : std::runtime_error(d.message), diag(std::move(d)) {}
    LumenError(SourceLoc loc, const std::string& msg, std::string hint = {})
        : LumenError(Diagnostic{Severity::Error, loc, msg, std::move(hint), {}}) {}
};

// Formats a diagnostic as several lines ending in '\n':
//   scene.pov:12:5: error: unknown keyword 'spere'
//       spere { 0, 1 }
//       ^
//   scene.pov:12:5: note: did you mean 'sphere'?
//   in file included from main.pov:3:1
std::string format_diagnostic(const Diagnostic& d);

// Just the first line of format_diagnostic, without the newline:
//   scene.pov:12:5: error: unknown keyword 'spere'
std::string format_headline(const Diagnostic& d);

// `s` as it may go to a terminal: bytes that are not valid UTF-8, and control characters
// other than tab (and newline when `keep_newlines`), become \xNN, so that a binary or
// mis-encoded file never sends raw bytes to the terminal (base/printable.cpp).
std::string printable(std::string_view s, bool keep_newlines);
// The number of characters (code points) in printable text.
size_t display_width(std::string_view printable_text);

// The candidate closest to `word` by edit distance, if it is close enough to be a likely
// misspelling; empty otherwise.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

// Convenience: "did you mean 'x'?" or empty.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace lumen

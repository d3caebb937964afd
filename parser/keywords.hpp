// Keyword classification for the SDL grammar: which words are reserved, which reserved words
// may stand in an expression (constants, built-in functions), which start a colour, and which
// name blocks (for "did you mean" suggestions).
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace lumen::parser {

// POV-Ray 3.7's reserved keywords (sorted).
const std::vector<std::string>& reserved_words();
// Words that usually introduce a `{ }` block (sphere, pigment, color_map, ...).
const std::vector<std::string>& block_keywords();

bool is_reserved(std::string_view word);
// Constants and built-in functions: parsed as Ident / Call, never as Keyword items.
bool is_expression_word(std::string_view word);
// color / colour.
bool is_colour_keyword(std::string_view word);
// rgb rgbf rgbt rgbft srgb srgbf srgbt srgbft.
bool is_rgb_word(std::string_view word);
// red green blue filter transmit gray grey (a colour component part).
bool is_component_word(std::string_view word);
// Directive words that may start a `#` directive.
bool is_directive_word(std::string_view word);

}  // namespace lumen::parser

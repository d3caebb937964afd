// Public entry points of the SDL parser (PEGTL grammar -> ast::Node).
#pragma once
#include <stdexcept>
#include <string>

#include "parser/ast.hpp"

namespace lumen::parser {

// A syntax error with the location where it was detected.
struct ParseError : std::runtime_error {
    SourceLoc loc;
    std::string hint;  // optional "did you mean ..." or similar, may be empty
    ParseError(SourceLoc l, const std::string& msg, std::string h = {})
        : std::runtime_error(msg), loc(l), hint(std::move(h)) {}
};

// Parses a whole file into a Body node. Throws ParseError, also for a binary or UTF-16 file
// (text_encoding.hpp).
// Nesting (parentheses, vectors, blocks, directives, unary operators) deeper than
// kMaxNesting gives a ParseError instead of a stack overflow.
ast::NodePtr parse_file(const SourceFile& file);

// Parses `length` bytes of file->text starting at byte offset `begin` (whose location is
// `start`) as a Body: used for macro bodies. Throws ParseError.
ast::NodePtr parse_fragment(const SourceFile& file, uint32_t begin, uint32_t end, SourceLoc start);

// Parses a single expression from a string (command-line Declare=, tests). Throws ParseError.
ast::NodePtr parse_expression(const SourceFile& file);

constexpr int kMaxNesting = 400;

// True if `word` is a reserved SDL keyword (as listed in POV-Ray 3.7's reference).
bool is_reserved_word(const std::string& word);

}  // namespace lumen::parser

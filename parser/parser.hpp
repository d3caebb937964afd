// Public entry points of the SDL parser (PEGTL grammar -> ast::Node).
#pragma once
#include <stdexcept>
#include <string>

#include "base/diagnostics.hpp"
#include "parser/ast.hpp"

namespace lumen::parser {

// Parses a whole file into a Body node. Throws LumenError at the first syntax error, also
// for a binary or UTF-16 file (text_encoding.hpp).
// Nesting (parentheses, vectors, blocks, directives, unary operators) deeper than
// kMaxNesting gives a LumenError instead of a stack overflow.
ast::NodePtr parse_file(const SourceFile& file);

// Parses `length` bytes of file->text starting at byte offset `begin` (whose location is
// `start`) as a Body: used for macro bodies. Throws LumenError.
ast::NodePtr parse_fragment(const SourceFile& file, uint32_t begin, uint32_t end, SourceLoc start);

// Parses a single expression from a string (command-line Declare=, tests). Throws LumenError.
ast::NodePtr parse_expression(const SourceFile& file);
// Parses bytes [begin, end) of file->text (whose location is `start`) as a single expression:
// a directive's condition read out of a macro body. Throws LumenError.
ast::NodePtr parse_expression(const SourceFile& file, uint32_t begin, uint32_t end, SourceLoc start);

constexpr int kMaxNesting = 400;

// True if `word` is a reserved SDL keyword (as listed in POV-Ray 3.7's reference).
bool is_reserved_word(const std::string& word);

}  // namespace lumen::parser

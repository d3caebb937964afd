// A compact S-expression rendering of a syntax tree, for tests and debugging:
//   (Block sphere (Vector (Number 0) (Number 0) (Number 0)) (Comma) (Number 1))
#pragma once
#include <string>

#include "parser/ast.hpp"

namespace lumen::parser {

std::string dump(const ast::Node& n);

}  // namespace lumen::parser

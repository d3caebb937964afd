// The items of a literal run (ast::LiteralRun): the parser keeps a block's long lists of
// floats and vectors as arrays, and the evaluator hands such a run on as one Literals item.
// Its elements become items only when read, one at a time (ItemCursor), each with the value
// and location the evaluator would have given the same text.
#pragma once
#include <vector>

#include "interp/value.hpp"

namespace lumen::interp {

// Element i of `run`, whose values start at run.values[offset]: a comma, a float or a vector.
Item literal_item(const ast::LiteralRun& run, size_t i, size_t offset, const SourceFile* file);

// Replaces each Literals item by its elements' items, for the few readers that count or
// index items instead of reading them through an ItemCursor.
void expand_literals(std::vector<Item>& items);

}  // namespace lumen::interp

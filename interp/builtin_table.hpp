// The built-in function table's entry type, shared by builtins.cpp and math_builtins.cpp.
#pragma once
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "interp/evaluator.hpp"

namespace lumen::interp {

using Args = std::vector<Value>;
using Fn = std::function<Value(Evaluator&, const ast::Node&, Args&)>;

struct Builtin {
    int min_args, max_args;  // max -1 = any number
    bool lazy;               // receives no evaluated arguments: reads the call node itself
    Fn fn;
};

using BuiltinTable = std::unordered_map<std::string, Builtin>;

// abs .. tanh, atan2, div, mod, pow, min, max, bitwise_*: with POV-Ray's domain rules.
void add_math_builtins(BuiltinTable& t);
// min_extent, max_extent, trace, inside: questions about an object.
void add_object_builtins(BuiltinTable& t);

}  // namespace lumen::interp

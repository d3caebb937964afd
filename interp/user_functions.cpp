// Calling a user-defined `function { ... }` from an expression (`#declare V = F(1, 2, 3);`).
// The body is evaluated as an ordinary expression with the parameters bound as locals
// (x, y, z when the function declares none). Pattern functions (`function { pigment {...} }`),
// POV's `internal(n)` functions and splines cannot be evaluated and give an error.
#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"

namespace lumen::interp {

Value Evaluator::call_function(const FunctionValue& fn, const ast::Node& call) {
    const ast::Node& node = *fn.node;
    auto refuse = [&](const std::string& why) -> Value {
        throw LumenError(call.loc, "cannot evaluate " + fn.keyword + " '" + call.text + "' here: " + why);
    };
    if (fn.keyword != "function") return refuse("only functions can be called in expressions");
    if (node.children.size() != 1) return refuse("its body is not a single expression");
    const ast::Node& body = *node.children[0];
    if (body.kind == ast::Kind::Block) return refuse("'" + body.text + "' functions are not supported");
    if (body.kind == ast::Kind::Call && body.text == "internal")
        return refuse("POV-Ray's internal functions are not supported");

    static const std::vector<std::string> kDefaultParams = {"x", "y", "z"};
    const std::vector<std::string>& params = node.params.empty() ? kDefaultParams : node.params;
    if (call.children.size() != params.size())
        throw LumenError(call.loc, "function '" + call.text + "' takes " + std::to_string(params.size()) +
                                       " argument(s), found " + std::to_string(call.children.size()));
    std::vector<Value> args;
    for (const auto& a : call.children) args.push_back(Value{eval_float(*a), a->loc});
    if (macro_depth_ >= options_.max_macro_depth)
        throw LumenError(call.loc, "function '" + call.text + "' nested more than " +
                                       std::to_string(options_.max_macro_depth) + " calls deep");
    budget.step(call.loc);
    ScopedSet depth(macro_depth_, macro_depth_ + 1);
    ScopedSet vm(in_function_body_, true);
    FrameGuard frame(symbols);
    for (size_t i = 0; i < params.size(); ++i) symbols.local(params[i], std::move(args[i]));
    Value result = eval(body);
    result.loc = call.loc;
    return result;
}

double Evaluator::eval_at(const ast::Node& expr, double x, double y, double z) {
    budget.step(expr.loc);
    ScopedSet vm(in_function_body_, true);
    FrameGuard frame(symbols);
    symbols.local("x", Value{x, expr.loc});
    symbols.local("y", Value{y, expr.loc});
    symbols.local("z", Value{z, expr.loc});
    return eval_float(expr);
}

}  // namespace lumen::interp

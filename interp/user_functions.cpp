// `function { ... }` and `spline { ... }` blocks as values, and calling them from an expression
// (`#declare V = F(1, 2, 3);`, `S(t)`): the program compiled at the declaration
// (compile_function.cpp, compile_vector_function.cpp) runs in the same VM the renderer uses,
// so a function has one meaning wherever it is called. Pigment and pattern functions need the
// renderer's host (InterpOptions::function_host).
#include "interp/build_common.hpp"
#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"

namespace lumen::interp {

fn::Context Evaluator::function_context() const { return ctx.function_context(); }

Value Evaluator::function_block(const ast::Node& block) {
    const std::string& kw = block.text;
    FunctionValue f{&block, kw, nullptr, {}, nullptr};
    if (kw == "spline") {
        BlockValue bv{kw, flatten_sealed(block.children), block.loc};
        ItemCursor cur(ctx, bv);
        f.spline = build_spline(cur);
        f.why_not = "a spline is called as S(t) in a scene, or through function { spline { S } }";
    } else if (kw != "function") {
        f.why_not = kw + " functions are not supported";
    } else if (block.children.empty()) {
        throw LumenError(block.loc, "a function needs a body");
    } else if (const ast::Node& body = *block.children.back(); body.kind == ast::Kind::Block) {
        if (body.text != "pigment" && body.text != "pattern" && body.text != "transform" &&
            body.text != "spline")
            throw LumenError(body.loc, "a function's body is an expression or a pigment, "
                                       "pattern, transform or spline block, not '" +
                                           body.text + "'");
        f.program = compile_vector_function(block);
    } else {
        f.program = compile_function(block);
    }
    return Value{std::make_shared<const FunctionValue>(std::move(f)), block.loc};
}

Value Evaluator::call_function(const FunctionValue& fn, const ast::Node& call) {
    if (fn.spline) return call_spline(*fn.spline, call);
    if (!fn.program) {
        const std::string why = fn.keyword != "function" ? "only functions can be called in expressions"
                                                         : fn.why_not;
        throw LumenError(call.loc, "cannot evaluate " + fn.keyword + " '" + call.text + "' here: " + why);
    }
    const fn::Program& program = *fn.program;
    if (call.children.size() != size_t(program.params))
        throw LumenError(call.loc, "function '" + call.text + "' takes " +
                                       std::to_string(program.params) + " argument(s), found " +
                                       std::to_string(call.children.size()));
    if (program.needs_host && !options_.function_host)
        throw LumenError(call.loc, "cannot evaluate " + fn.keyword + " '" + call.text +
                                       "' here: pigment and pattern functions need the renderer");
    std::vector<double> args;
    for (const auto& a : call.children) args.push_back(eval_float(*a));
    budget.step(call.loc);
    if (program.components == 1)
        return Value{fn::evaluate(program, args, function_context()), call.loc};
    // A vector function returns every component: a pigment's 5, a transform's 3.
    VecN v;
    for (int c = 0; c < program.components; ++c)
        v.c.push_back(fn::evaluate(program, args, function_context(), c));
    return Value{std::move(v), call.loc};
}

// S(t) or S(t, linear_spline | quadratic_spline | cubic_spline | natural_spline): the spline's
// value, a vector of its `terms` components (a float spline gives <v, v>).
Value Evaluator::call_spline(const fn::Spline& spline, const ast::Node& call) {
    const size_t argc = call.children.size();
    if (argc != 1 && argc != 2)
        throw LumenError(call.loc, "spline '" + call.text + "' takes t and optionally a spline type");
    fn::SplineType type = spline.type;
    if (argc == 2) {
        const ast::Node& kind = *call.children[1];
        const auto named = kind.kind == ast::Kind::Ident ? spline_type(kind.text) : std::nullopt;
        if (!named)
            throw LumenError(kind.loc, "expected linear_spline, quadratic_spline, cubic_spline or "
                                       "natural_spline");
        type = *named;
    }
    const std::array<double, 5> v = spline.at(eval_float(*call.children[0]), type);
    budget.step(call.loc);
    return Value{VecN{std::vector<double>(v.begin(), v.begin() + spline.terms)}, call.loc};
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

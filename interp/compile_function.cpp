// `function { ... }` compiled into a fn::Program where it is declared, with POV-Ray 3.7's
// function language (not SDL's): `&` binds tighter than `|`, comparisons are exact, only the
// calls POV allows, declared floats copied in at declaration, division by a constant turned
// into multiplication by its reciprocal and small integer powers into products (POV's
// rewrites, which change the last bits), constants folded.
#include <cmath>
#include <numbers>

#include "function/internal.hpp"
#include "function/vm.hpp"
#include "interp/evaluator.hpp"

namespace lumen::interp {

namespace {

using fn::Instr;
using fn::Op;

struct Math1Name {
    const char* name;
    fn::Math1 f;
};
constexpr Math1Name kMath1[] = {
    {"sin", fn::Math1::Sin},     {"cos", fn::Math1::Cos},     {"tan", fn::Math1::Tan},
    {"asin", fn::Math1::Asin},   {"acos", fn::Math1::Acos},   {"atan", fn::Math1::Atan},
    {"sinh", fn::Math1::Sinh},   {"cosh", fn::Math1::Cosh},   {"tanh", fn::Math1::Tanh},
    {"asinh", fn::Math1::Asinh}, {"acosh", fn::Math1::Acosh}, {"atanh", fn::Math1::Atanh},
    {"abs", fn::Math1::Abs},     {"floor", fn::Math1::Floor}, {"ceil", fn::Math1::Ceil},
    {"sqrt", fn::Math1::Sqrt},   {"exp", fn::Math1::Exp},     {"ln", fn::Math1::Ln},
    {"log", fn::Math1::Log},     {"int", fn::Math1::Int},     {"radians", fn::Math1::Radians},
    {"degrees", fn::Math1::Degrees},
};
struct Math2Name {
    const char* name;
    fn::Math2 f;
};
constexpr Math2Name kMath2[] = {
    {"atan2", fn::Math2::Atan2}, {"pow", fn::Math2::Pow}, {"mod", fn::Math2::Mod},
    {"div", fn::Math2::Div}};


class Compiler {
public:
    Compiler(Evaluator& ev, const ast::Node& block) : ev_(ev) {
        if (block.more().params.empty()) {
            params_ = {"x", "y", "z"};
        } else {
            params_ = block.more().params;
        }
        if (params_.size() > size_t(fn::kMaxParams))
            fail(block.loc, "a function takes at most " + std::to_string(fn::kMaxParams) +
                                " parameters, as in POV-Ray; this one names " +
                                std::to_string(params_.size()));
        p_.params = int(params_.size());
    }

    fn::ProgramPtr body(const ast::Node& e) {
        expr(e);
        return std::make_shared<const fn::Program>(std::move(p_));
    }

    // `function { internal(N) }`.
    fn::ProgramPtr internal(const ast::Node& call) {
        if (call.children.size() != 1) fail(call.loc, "internal() takes one argument");
        const double n = ev_.eval_float(*call.children[0]);
        if (!(n >= 0 && n < fn::kInternalCount) || n != std::trunc(n))
            fail(call.children[0]->loc, "there is no internal function " + number(n));
        const fn::InternalInfo& info = fn::internal_info(int(n));
        p_.params = 3 + info.params;
        for (int i = 0; i < p_.params; ++i) emit({Op::Arg, 0, 0, uint32_t(i)}, +1);
        emit({Op::Internal, 0, uint16_t(p_.params), uint32_t(n)}, 1 - p_.params);
        return std::make_shared<const fn::Program>(std::move(p_));
    }

private:
    [[noreturn]] void fail(SourceLoc loc, const std::string& why) { throw LumenError(loc, why); }
    static std::string number(double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        return buf;
    }

    void emit(Instr in, int stack_change) {
        p_.code.push_back(in);
        depth_ += stack_change;
        if (depth_ > fn::kMaxStack)
            fail(loc_, "the function is nested too deeply (more than " +
                           std::to_string(fn::kMaxStack) + " pending values)");
    }
    void constant(double v) {
        p_.consts.push_back(v);
        emit({Op::Const, 0, 0, uint32_t(p_.consts.size() - 1)}, +1);
    }
    // Whether the code from `start` is one constant; its value.
    bool is_const(size_t start, double& v) const {
        if (p_.code.size() != start + 1 || p_.code[start].op != Op::Const) return false;
        v = p_.consts[p_.code[start].a];
        return true;
    }
    // Replaces the code from `start` (constants only) by the constant v.
    void fold(size_t start, double v, int pushed) {
        p_.code.resize(start);
        depth_ -= pushed;
        constant(v);
    }
    // When the code from `start` is `operands` constants and nothing else, replaces it by `op`
    // applied to them, as the VM computes it (folding never differs from running); else false.
    bool fold_constants(size_t start, Instr op, int operands) {
        if (p_.code.size() != start + size_t(operands)) return false;
        fn::Program p;
        p.params = 0;
        for (size_t i = start; i < p_.code.size(); ++i) {
            if (p_.code[i].op != Op::Const) return false;
            p.consts.push_back(p_.consts[p_.code[i].a]);
            p.code.push_back({Op::Const, 0, 0, uint32_t(p.consts.size() - 1)});
        }
        p.code.push_back(op);
        fold(start, fn::evaluate(p, {}), operands);
        return true;
    }
    // Locals are taken for the code of one call (pow's temporaries, select's test, sum's
    // counter) and given back after it (Scope), so only nesting uses them up.
    int new_local(SourceLoc loc) {
        if (in_use_ >= fn::kMaxLocals) fail(loc, "too many nested sum(), prod() and select() calls");
        return in_use_++;
    }
    struct Scope {
        Compiler& c;
        int saved;
        explicit Scope(Compiler& compiler) : c(compiler), saved(compiler.in_use_) {}
        ~Scope() { c.in_use_ = saved; }
    };

    void expr(const ast::Node& e) {
        loc_ = e.loc;
        using ast::Kind;
        switch (e.kind) {
            case Kind::Number: constant(e.number); return;
            case Kind::Ident: return ident(e);
            case Kind::Unary: {
                if (e.text == "!")
                    fail(e.loc, "'!' is not available in functions (write 1 - (a != 0))");
                const size_t start = p_.code.size();
                expr(*e.children.at(0));
                if (e.text != "-") return;
                if (!fold_constants(start, {Op::Neg}, 1)) emit({Op::Neg}, 0);
                return;
            }
            case Kind::Binary: return binary(e);
            case Kind::Call: return call(e);
            case Kind::Ternary:
                fail(e.loc, "'? :' is not available in functions (use select())");
            case Kind::Member: return member(e);
            default:
                fail(e.loc, std::string("a function body cannot contain ") + ast::kind_name(e.kind));
        }
    }

    void ident(const ast::Node& e) {
        const std::string& n = e.text;
        for (const Local& l : locals_)  // innermost first
            if (l.name == n) return emit({Op::Local, 0, 0, uint32_t(l.slot)}, +1);
        for (size_t i = 0; i < params_.size(); ++i)
            if (params_[i] == n) return emit({Op::Arg, 0, 0, uint32_t(i)}, +1);
        // x and u are one slot, y and v another: either name reads the parameter named by the
        // other; a slot no parameter names reads 0.
        const int slot = n == "x" || n == "u" ? 0 : n == "y" || n == "v" ? 1 : n == "z" ? 2 : -1;
        if (slot >= 0) {
            static const char* kNames[3][2] = {{"x", "u"}, {"y", "v"}, {"z", "z"}};
            for (size_t i = 0; i < params_.size(); ++i)
                if (params_[i] == kNames[slot][0] || params_[i] == kNames[slot][1])
                    return emit({Op::Arg, 0, 0, uint32_t(i)}, +1);
            return constant(0);
        }
        const Value v = ev_.lookup(e);  // undeclared: the evaluator's own error
        if (v.is<double>()) return constant(v.as<double>());
        if (v.is<std::shared_ptr<const FunctionValue>>())
            fail(e.loc, "function '" + n + "' must be called with its arguments: " + n + "(...)");
        fail(e.loc, "'" + n + "' is a " + v.type_name() +
                        ": a function can only use float identifiers and other functions");
    }

    // One flat chain of the parser (SDL puts & and | on one level; functions bind & tighter).
    void binary(const ast::Node& e) {
        const auto& ops = e.more().ops;
        bool has_or = false, has_and = false;
        for (const std::string& op : ops) has_or |= op == "|", has_and |= op == "&";
        if (has_or && has_and) {
            // Split at each | into groups joined by &.
            size_t i = 0;
            bool first = true;
            while (i < e.children.size()) {
                size_t j = i;
                while (j < ops.size() && ops[j] == "&") ++j;
                and_group(e, i, j);
                if (!first) emit({Op::Or}, -1);
                first = false;
                i = j + 1;
            }
            return;
        }
        const size_t start = p_.code.size();
        expr(*e.children[0]);
        for (size_t k = 0; k < ops.size(); ++k) operand(ops[k], *e.children[k + 1], start);
    }
    void and_group(const ast::Node& e, size_t from, size_t to) {  // children from..to
        expr(*e.children[from]);
        for (size_t k = from; k < to; ++k) {
            expr(*e.children[k + 1]);
            emit({Op::And}, -1);
        }
    }
    // Emits `op operand` after the left side (from `start`), folding constants.
    void operand(const std::string& written, const ast::Node& right, size_t start) {
        const size_t rstart = p_.code.size();
        expr(right);
        loc_ = right.loc;
        double b = 0;
        const bool rconst = is_const(rstart, b);
        std::string op = written;
        if (op == "/" && rconst) {
            if (b == 0) fail(right.loc, "division by zero");
            // POV multiplies by the reciprocal of a constant divisor.
            p_.code.resize(rstart);
            --depth_;
            constant(1 / b);
            op = "*";
        }
        if (fold_constants(start, {op_of(op)}, 2)) return;
        if (rconst && (op == "+" || op == "-" || op == "*")) {
            // One instruction for `e op constant` (the same arithmetic, fewer dispatches).
            const uint32_t k = p_.code[rstart].a;
            p_.code.resize(rstart);
            --depth_;
            return emit({op == "+" ? Op::AddConst : op == "-" ? Op::SubConst : Op::MulConst, 0, 0, k}, 0);
        }
        emit({op_of(op)}, -1);
    }
    static Op op_of(const std::string& op) {
        if (op == "+") return Op::Add;
        if (op == "-") return Op::Sub;
        if (op == "*") return Op::Mul;
        if (op == "/") return Op::Div;
        if (op == "<") return Op::Lt;
        if (op == "<=") return Op::Le;
        if (op == "=") return Op::Eq;
        if (op == "!=") return Op::Ne;
        if (op == ">=") return Op::Ge;
        if (op == ">") return Op::Gt;
        if (op == "&") return Op::And;
        return Op::Or;
    }

    void call(const ast::Node& e) {
        const std::string& n = e.text;
        const size_t argc = e.children.size();
        auto want = [&](size_t lo, size_t hi) {
            if (argc < lo || argc > hi)
                fail(e.loc, "'" + n + "' takes " +
                                (lo == hi ? std::to_string(lo) : std::to_string(lo) + " or more") +
                                " argument(s) in a function, found " + std::to_string(argc));
        };
        for (const Math1Name& m : kMath1)
            if (n == m.name) {
                want(1, 1);
                const size_t start = p_.code.size();
                expr(*e.children[0]);
                double v = 0;
                if (is_const(start, v) && (m.f == fn::Math1::Ln || m.f == fn::Math1::Log) && v <= 0)
                    fail(e.loc, "the logarithm of " + number(v) + " is undefined");
                const Instr in{Op::Math1, 0, 0, uint32_t(m.f)};
                if (!fold_constants(start, in, 1)) emit(in, 0);
                return;
            }
        for (const Math2Name& m : kMath2)
            if (n == m.name) {
                want(2, 2);
                if (m.f == fn::Math2::Pow) return power(e);
                const size_t start = p_.code.size();
                expr(*e.children[0]);
                expr(*e.children[1]);
                const Instr in{Op::Math2, 0, 0, uint32_t(m.f)};
                if (!fold_constants(start, in, 2)) emit(in, -1);
                return;
            }
        if (n == "min" || n == "max") {
            want(2, 1000);
            expr(*e.children[0]);
            for (size_t i = 1; i < argc; ++i) {
                expr(*e.children[i]);
                emit({n == "min" ? Op::Min : Op::Max}, -1);
            }
            return;
        }
        if (n == "select") return select(e);
        if (n == "sum" || n == "prod") return sum(e);
        if (n == "internal") fail(e.loc, "internal() must be a function's whole body");
        if (const Value* v = ev_.symbols.find(n); v && v->is<std::shared_ptr<const FunctionValue>>()) {
            const FunctionValue& f = *v->as<std::shared_ptr<const FunctionValue>>();
            if (f.program && f.program->components > 1)
                fail(e.loc, "'" + n + "' is a vector function: take one member of its result, "
                            "e.g. " + n + "(...).x or .red");
            return call_declared(e, f, 0);
        }
        fail(e.loc, "'" + n + "' cannot be called in a function (POV-Ray allows its math "
                              "functions, select, sum, prod, min, max and declared functions)");
    }

    // A declared function's call; `member` picks a vector function's component.
    void call_declared(const ast::Node& e, const FunctionValue& f, uint8_t member) {
        const std::string& n = e.text;
        const size_t argc = e.children.size();
        if (!f.program) fail(e.loc, "cannot call '" + n + "' in a function: " + f.why_not);
        if (int(argc) != f.program->params)
            fail(e.loc, "function '" + n + "' takes " + std::to_string(f.program->params) +
                            " argument(s), found " + std::to_string(argc));
        for (const auto& a : e.children) expr(*a);
        if (inline_wrapper(*f.program, member)) return;
        p_.callees.push_back(f.program);
        p_.needs_host = p_.needs_host || f.program->needs_host;
        emit({Op::Call, member, uint16_t(argc), uint32_t(p_.callees.size() - 1)}, 1 - int(argc));
    }

    // A callee that only passes its arguments on, in order, to one internal function, external
    // or transform (functions.inc's f_*, pigment and pattern functions) is that instruction
    // here, not a call: its arguments are already on the stack.
    bool inline_wrapper(const fn::Program& callee, uint8_t member) {
        const size_t n = size_t(callee.params);
        if (callee.code.size() != n + 1) return false;
        for (size_t i = 0; i < n; ++i)
            if (callee.code[i].op != Op::Arg || callee.code[i].a != i) return false;
        Instr last = callee.code[n];
        if (last.op == Op::Internal) {
            emit(last, 1 - int(n));
            return true;
        }
        if (last.op == Op::External) {
            p_.externals.push_back(callee.externals[last.a]);
            last.a = uint32_t(p_.externals.size() - 1);
        } else if (last.op == Op::Spline) {
            p_.splines.push_back(callee.splines[last.a]);
            last.a = uint32_t(p_.splines.size() - 1);
        } else if (last.op == Op::Transform) {
            const uint32_t at = uint32_t(p_.consts.size());
            p_.consts.insert(p_.consts.end(), callee.consts.begin() + last.a,
                             callee.consts.begin() + last.a + 12);
            last.a = at;
        } else {
            return false;
        }
        if (last.c == fn::kMemberAsked) last.c = member;
        p_.needs_host = p_.needs_host || callee.needs_host;
        emit(last, 1 - int(n));
        return true;
    }

    // F(...).member, F a vector function (pigment: 5 components, transform: 3).
    void member(const ast::Node& e) {
        const ast::Node& base = *e.children.at(0);
        const Value* v = base.kind == ast::Kind::Call ? ev_.symbols.find(base.text) : nullptr;
        if (!v || !v->is<std::shared_ptr<const FunctionValue>>())
            fail(e.loc, "in a function only a vector function's result has members");
        const FunctionValue& f = *v->as<std::shared_ptr<const FunctionValue>>();
        if (f.program && f.program->components == 1)
            fail(e.loc, "'" + base.text + "' is a float function: its result has no members");
        const std::string& m = e.text;
        uint8_t index;
        if (m == "x" || m == "u" || m == "red") index = 0;
        else if (m == "y" || m == "v" || m == "green") index = 1;
        else if (m == "z" || m == "blue") index = 2;
        else if (m == "t" || m == "filter") index = 3;
        else if (m == "transmit") index = 4;
        else if (m == "gray" || m == "grey") index = fn::kMemberGray;
        else if (m == "hf") index = fn::kMemberHf;
        else fail(e.loc, "unknown member '." + m + "'");
        call_declared(base, f, index);
    }

    // pow(e, c): a literal 0 is 1 (with POV's warning), 2..8 products of e, else C's pow.
    void power(const ast::Node& e) {
        const size_t start = p_.code.size();
        expr(*e.children[0]);
        const size_t rstart = p_.code.size();
        expr(*e.children[1]);
        const Instr pow{Op::Math2, 0, 0, uint32_t(fn::Math2::Pow)};
        if (fold_constants(start, pow, 2)) return;
        double c = 0;
        if (is_const(rstart, c)) {
            if (c == 0) {
                ev_.warn(e.loc, "zero power optimised to constant 1.0");
                p_.code.resize(start);
                depth_ -= 2;
                return constant(1);
            }
            if (c >= 2 && c <= 8 && c == std::trunc(c)) {
                Scope scope(*this);
                p_.code.resize(rstart);
                --depth_;
                const uint32_t t = uint32_t(new_local(e.loc));
                emit({Op::SetLocal, 0, 0, t}, -1);
                auto b = [&] { emit({Op::Local, 0, 0, t}, +1); };
                auto mul = [&] { emit({Op::Mul}, -1); };
                auto square = [&] { b(), b(), mul(); };   // b²
                auto fourth = [&] { square(), square_top(); };
                switch (int(c)) {
                    case 2: square(); break;
                    case 3: square(), b(), mul(); break;
                    case 4: fourth(); break;
                    case 5: fourth(), b(), mul(); break;
                    case 6: fourth(), square(), mul(); break;
                    case 7: fourth(), b(), mul(), square(), mul(); break;
                    case 8: fourth(), square_top(); break;
                }
                return;
            }
        }
        emit(pow, -1);
    }
    // Squares the value on top of the stack through a fresh local.
    void square_top() {
        const uint32_t s = uint32_t(new_local(loc_));
        emit({Op::SetLocal, 0, 0, s}, -1);
        emit({Op::Local, 0, 0, s}, +1);
        emit({Op::Local, 0, 0, s}, +1);
        emit({Op::Mul}, -1);
    }

    // select(A, B, C): A < 0 ? B : C; select(A, B, C, D): A < 0 ? B : A = 0 ? C : D. Only the
    // chosen branch runs; NaN takes the last.
    void select(const ast::Node& e) {
        const size_t argc = e.children.size();
        if (argc != 3 && argc != 4)
            fail(e.loc, "select() takes 3 or 4 arguments, found " + std::to_string(argc));
        if (argc == 3) {
            expr(*e.children[0]);
            const size_t end = branch(Op::JumpIfNotNeg, *e.children[1]);
            expr(*e.children[2]);
            p_.code[end].a = uint32_t(p_.code.size());
            return;
        }
        Scope scope(*this);
        const uint32_t t = uint32_t(new_local(e.loc));
        expr(*e.children[0]);
        emit({Op::SetLocal, 0, 0, t}, -1);
        emit({Op::Local, 0, 0, t}, +1);
        const size_t end1 = branch(Op::JumpIfNotNeg, *e.children[1]);
        emit({Op::Local, 0, 0, t}, +1);
        const size_t end2 = branch(Op::JumpIfNotZero, *e.children[2]);
        expr(*e.children[3]);
        p_.code[end1].a = p_.code[end2].a = uint32_t(p_.code.size());
    }
    // One branch of a select: `then` behind the test `skip` (which pops the tested value and
    // jumps past it), then a jump over what follows, whose index is returned to be pointed at
    // the end.
    size_t branch(Op skip, const ast::Node& then) {
        const size_t test = p_.code.size();
        emit({skip}, -1);
        expr(then);
        const size_t over = p_.code.size();
        emit({Op::Jump}, 0);
        --depth_;  // the next branch pushes the same one value
        p_.code[test].a = uint32_t(p_.code.size());
        return over;
    }

    // sum(i, a, b, E) / prod(i, a, b, E): i = a, a + 1, ... while i <= b (b evaluated once).
    void sum(const ast::Node& e) {
        if (e.children.size() != 4)
            fail(e.loc, e.text + "() takes 4 arguments (variable, from, to, expression)");
        const ast::Node& var = *e.children[0];
        if (var.kind != ast::Kind::Ident) fail(var.loc, "expected the name of the loop variable");
        const bool product = e.text == "prod";
        Scope scope(*this);
        const uint32_t i = uint32_t(new_local(e.loc)), limit = uint32_t(new_local(e.loc)),
                       acc = uint32_t(new_local(e.loc));
        expr(*e.children[1]);
        emit({Op::SetLocal, 0, 0, i}, -1);
        expr(*e.children[2]);
        emit({Op::SetLocal, 0, 0, limit}, -1);
        constant(product ? 1 : 0);
        emit({Op::SetLocal, 0, 0, acc}, -1);
        const uint32_t top = uint32_t(p_.code.size());
        emit({Op::Local, 0, 0, i}, +1);
        emit({Op::Local, 0, 0, limit}, +1);
        const size_t exit = p_.code.size();
        emit({Op::JumpIfGreater}, -2);
        emit({Op::Local, 0, 0, acc}, +1);
        locals_.insert(locals_.begin(), Local{var.text, int(i)});
        expr(*e.children[3]);
        locals_.erase(locals_.begin());
        emit({product ? Op::Mul : Op::Add}, -1);
        emit({Op::SetLocal, 0, 0, acc}, -1);
        emit({Op::Local, 0, 0, i}, +1);
        constant(1);
        emit({Op::Add}, -1);
        emit({Op::SetLocal, 0, 0, i}, -1);
        emit({Op::Jump, 0, 0, top}, 0);
        p_.code[exit].a = uint32_t(p_.code.size());
        emit({Op::Local, 0, 0, acc}, +1);
    }

    struct Local {
        std::string name;
        int slot;
    };
    Evaluator& ev_;
    fn::Program p_;
    std::vector<std::string> params_;
    std::vector<Local> locals_;
    int depth_ = 0;
    int in_use_ = 0;  // locals taken
    SourceLoc loc_;
};

}  // namespace

fn::ProgramPtr Evaluator::compile_function(const ast::Node& block) {
    const ast::Node& body = *block.children.back();
    Compiler c(*this, block);
    if (body.kind == ast::Kind::Call && body.text == "internal") return c.internal(body);
    return c.body(body);
}

}  // namespace lumen::interp

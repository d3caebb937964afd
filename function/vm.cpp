#include "function/vm.hpp"

#include <cmath>
#include <numbers>

#include "function/internal.hpp"

namespace lumen::fn {

namespace {

double math1(Math1 f, double v) {
    switch (f) {
        case Math1::Sin: return std::sin(v);
        case Math1::Cos: return std::cos(v);
        case Math1::Tan: return std::tan(v);
        case Math1::Asin: return std::asin(v);
        case Math1::Acos: return std::acos(v);
        case Math1::Atan: return std::atan(v);
        case Math1::Sinh: return std::sinh(v);
        case Math1::Cosh: return std::cosh(v);
        case Math1::Tanh: return std::tanh(v);
        case Math1::Asinh: return std::asinh(v);
        case Math1::Acosh: return std::acosh(v);
        case Math1::Atanh: return std::atanh(v);
        case Math1::Abs: return std::fabs(v);
        case Math1::Floor: return std::floor(v);
        case Math1::Ceil: return std::ceil(v);
        case Math1::Sqrt: return std::sqrt(v);
        case Math1::Exp: return std::exp(v);
        case Math1::Ln: return std::log(v);
        case Math1::Log: return std::log10(v);
        case Math1::Int: return std::trunc(v);
        case Math1::Radians: return v * (std::numbers::pi / 180);
        case Math1::Degrees: return v * (180 / std::numbers::pi);
    }
    return 0;
}

double math2(Math2 f, double a, double b) {
    switch (f) {
        case Math2::Atan2: return std::atan2(a, b);
        case Math2::Pow: return std::pow(a, b);
        case Math2::Mod: return std::fmod(a, b);
        case Math2::Div: return std::trunc(a / b);
    }
    return 0;
}

double run(const Program& p, const double* args, const Context& context, int component,
           int depth);

// Member m of a vector result (program.hpp's numbering).
double member(const double* c, int m) {
    if (m == kMemberGray) return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
    if (m == kMemberHf) return (c[0] + c[1] / 255) * 0.996093;
    return m >= 0 && m < 5 ? c[m] : 0;
}

// POV's min and max fold left to right: min(NaN, 5) = 5 but min(5, NaN) = NaN; max(5, NaN)
// = 5 but max(NaN, 5) = NaN.
double pov_min(double running, double next) { return running <= next ? running : next; }
double pov_max(double running, double next) { return next > running ? next : running; }

double run(const Program& p, const double* args, const Context& context, int component,
           int depth) {
    double stack[kMaxStack];
    double locals[kMaxLocals];
    int sp = 0;
    const Instr* code = p.code.data();
    const size_t n = p.code.size();
    for (size_t pc = 0; pc < n; ++pc) {
        const Instr& in = code[pc];
        switch (in.op) {
            case Op::Const: stack[sp++] = p.consts[in.a]; break;
            case Op::Arg: stack[sp++] = args[in.a]; break;
            case Op::Local: stack[sp++] = locals[in.a]; break;
            case Op::SetLocal: locals[in.a] = stack[--sp]; break;
            case Op::Add: --sp; stack[sp - 1] += stack[sp]; break;
            case Op::Sub: --sp; stack[sp - 1] -= stack[sp]; break;
            case Op::Mul: --sp; stack[sp - 1] *= stack[sp]; break;
            case Op::Div: --sp; stack[sp - 1] /= stack[sp]; break;
            case Op::Neg: stack[sp - 1] = -stack[sp - 1]; break;
            case Op::AddConst: stack[sp - 1] += p.consts[in.a]; break;
            case Op::SubConst: stack[sp - 1] -= p.consts[in.a]; break;
            case Op::MulConst: stack[sp - 1] *= p.consts[in.a]; break;
            case Op::Lt: --sp; stack[sp - 1] = stack[sp - 1] < stack[sp]; break;
            case Op::Le: --sp; stack[sp - 1] = stack[sp - 1] <= stack[sp]; break;
            case Op::Eq: --sp; stack[sp - 1] = stack[sp - 1] == stack[sp]; break;
            // POV implements these as "not less" and "not equal": NaN gives 1.
            case Op::Ne: --sp; stack[sp - 1] = !(stack[sp - 1] == stack[sp]); break;
            case Op::Ge: --sp; stack[sp - 1] = !(stack[sp - 1] < stack[sp]); break;
            case Op::Gt: --sp; stack[sp - 1] = !(stack[sp - 1] <= stack[sp]); break;
            case Op::And: --sp; stack[sp - 1] = (stack[sp - 1] != 0) && (stack[sp] != 0); break;
            case Op::Or: --sp; stack[sp - 1] = (stack[sp - 1] != 0) || (stack[sp] != 0); break;
            case Op::Math1: stack[sp - 1] = math1(Math1(in.a), stack[sp - 1]); break;
            case Op::Math2: --sp; stack[sp - 1] = math2(Math2(in.a), stack[sp - 1], stack[sp]); break;
            case Op::Min: --sp; stack[sp - 1] = pov_min(stack[sp - 1], stack[sp]); break;
            case Op::Max: --sp; stack[sp - 1] = pov_max(stack[sp - 1], stack[sp]); break;
            case Op::Jump: pc = size_t(in.a) - 1; break;
            case Op::JumpIfNotNeg: if (!(stack[--sp] < 0)) pc = size_t(in.a) - 1; break;
            case Op::JumpIfNotZero: if (!(stack[--sp] == 0)) pc = size_t(in.a) - 1; break;
            case Op::JumpIfGreater:
                sp -= 2;
                if (!(stack[sp] <= stack[sp + 1])) pc = size_t(in.a) - 1;
                break;
            case Op::Internal:
                sp -= in.b;
                stack[sp] = internal(int(in.a), stack + sp, context.noise_generator);
                ++sp;
                break;
            case Op::External: {
                sp -= 3;
                double out[5] = {0, 0, 0, 0, 0};
                if (context.host) context.host->evaluate(p.externals[in.a], stack + sp, out);
                else out[0] = out[1] = out[2] = out[3] = out[4] = std::nan("");
                stack[sp++] = member(out, in.c == kMemberAsked ? component : in.c);
                break;
            }
            case Op::Transform: {
                sp -= 3;
                const double* m = p.consts.data() + in.a;
                const double* v = stack + sp;
                double out[3];
                for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * v[0] + m[4 * r + 1] * v[1] + m[4 * r + 2] * v[2] + m[4 * r + 3];
                const int c = in.c == kMemberAsked ? component : in.c;
                stack[sp++] = c < 3 ? out[c] : 0;
                break;
            }
            case Op::Spline: {
                const std::array<double, 5> v = p.splines[in.a]->at(stack[sp - 1]);
                stack[sp - 1] = member(v.data(), in.c == kMemberAsked ? component : in.c);
                break;
            }
            case Op::Call: {
                sp -= in.b;
                const Program& callee = *p.callees[in.a];
                // Recursion is refused when functions are compiled; the depth only guards
                // against a chain longer than POV-Ray allows.
                stack[sp] = depth < kMaxCallDepth
                                ? run(callee, stack + sp, context, in.c, depth + 1)
                                : std::nan("");
                ++sp;
                break;
            }
        }
    }
    return sp > 0 ? stack[sp - 1] : 0;
}

}  // namespace

double evaluate(const Program& program, std::span<const double> args, const Context& context,
                int component) {
    return run(program, args.data(), context, component, 0);
}

}  // namespace lumen::fn

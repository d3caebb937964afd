#include "function/vm.hpp"

#include <cmath>
#include <cstring>
#include <numbers>

#include "function/internal.hpp"
#include "function/register_code.hpp"

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

// One run in a frame of N registers (N at least the program's frame).
template <int N>
double run_in(const RegisterCode& rc, const Program& p, const double* args,
              const Context& context, int component, int depth) {
    double r[N];
    if (rc.frame_consts > 0)  // (no constants: data() may be null, which memcpy may not take)
        std::memcpy(r, p.consts.data(), sizeof(double) * size_t(rc.frame_consts));
    double* const a = r + rc.frame_consts;
    for (int i = 0; i < rc.args; ++i) a[i] = i < p.params ? args[i] : 0.0;
    // Threaded dispatch (GCC's labels as values): each operation ends in its own jump to the
    // next, which the branch predictor learns per operation, not once for the whole loop.
    // The labels below carry the operations' names, in the enum's order.
#define LUMEN_ROP_LABEL(name) &&name,
    static void* const kLabels[] = {LUMEN_REGISTER_OPS(LUMEN_ROP_LABEL)};
#undef LUMEN_ROP_LABEL
    const RInstr* const code = rc.code.data();
    const RInstr* in = code;
#define LUMEN_NEXT goto* kLabels[size_t((++in)->op)]
#define LUMEN_JUMP(to) goto* kLabels[size_t((in = code + (to))->op)]
    goto* kLabels[size_t(in->op)];
Move: r[in->d] = r[in->s]; LUMEN_NEXT;
LoadConst: r[in->d] = p.consts[in->a]; LUMEN_NEXT;
Add: r[in->d] = r[in->s] + r[in->t]; LUMEN_NEXT;
Sub: r[in->d] = r[in->s] - r[in->t]; LUMEN_NEXT;
Mul: r[in->d] = r[in->s] * r[in->t]; LUMEN_NEXT;
Div: r[in->d] = r[in->s] / r[in->t]; LUMEN_NEXT;
Neg: r[in->d] = -r[in->s]; LUMEN_NEXT;
Lt: r[in->d] = r[in->s] < r[in->t]; LUMEN_NEXT;
Le: r[in->d] = r[in->s] <= r[in->t]; LUMEN_NEXT;
Eq: r[in->d] = r[in->s] == r[in->t]; LUMEN_NEXT;
// POV implements these as "not less" and "not equal": NaN gives 1.
Ne: r[in->d] = !(r[in->s] == r[in->t]); LUMEN_NEXT;
Ge: r[in->d] = !(r[in->s] < r[in->t]); LUMEN_NEXT;
Gt: r[in->d] = !(r[in->s] <= r[in->t]); LUMEN_NEXT;
And: r[in->d] = (r[in->s] != 0) && (r[in->t] != 0); LUMEN_NEXT;
Or: r[in->d] = (r[in->s] != 0) || (r[in->t] != 0); LUMEN_NEXT;
Math1: r[in->d] = math1(fn::Math1(in->a), r[in->s]); LUMEN_NEXT;
Math2: r[in->d] = math2(fn::Math2(in->a), r[in->s], r[in->t]); LUMEN_NEXT;
Min: r[in->d] = pov_min(r[in->s], r[in->t]); LUMEN_NEXT;
Max: r[in->d] = pov_max(r[in->s], r[in->t]); LUMEN_NEXT;
Jump: LUMEN_JUMP(in->a);
JumpIfNotNeg:
    if (!(r[in->s] < 0)) LUMEN_JUMP(in->a);
    LUMEN_NEXT;
JumpIfNotZero:
    if (!(r[in->s] == 0)) LUMEN_JUMP(in->a);
    LUMEN_NEXT;
JumpIfGreater:
    if (!(r[in->s] <= r[in->t])) LUMEN_JUMP(in->a);
    LUMEN_NEXT;
Internal:
    r[in->d] = internal(int(in->a), r + in->s, context.noise_generator);
    LUMEN_NEXT;
External: {
    double out[5] = {0, 0, 0, 0, 0};
    if (context.host) context.host->evaluate(p.externals[in->a], r + in->s, out);
    else out[0] = out[1] = out[2] = out[3] = out[4] = std::nan("");
    r[in->d] = member(out, in->c == kMemberAsked ? component : in->c);
    LUMEN_NEXT;
}
Transform: {
    const double* m = p.consts.data() + in->a;
    const double* v = r + in->s;
    double out[3];
    for (int i = 0; i < 3; ++i) out[i] = m[4 * i] * v[0] + m[4 * i + 1] * v[1] + m[4 * i + 2] * v[2] + m[4 * i + 3];
    const int c = in->c == kMemberAsked ? component : in->c;
    r[in->d] = c < 3 ? out[c] : 0;
    LUMEN_NEXT;
}
Spline: {
    const std::array<double, 5> v = p.splines[in->a]->at(r[in->s]);
    r[in->d] = member(v.data(), in->c == kMemberAsked ? component : in->c);
    LUMEN_NEXT;
}
Call:
    // Recursion is refused when functions are compiled; the depth only guards against a chain
    // longer than POV-Ray allows.
    r[in->d] = depth < kMaxCallDepth ? run(*p.callees[in->a], r + in->s, context, in->c, depth + 1)
                                     : std::nan("");
    LUMEN_NEXT;
Return:
    return in->a ? 0.0 : r[in->s];
#undef LUMEN_NEXT
#undef LUMEN_JUMP
}

// Small frames (most functions) take little of the C++ stack, which chains of calls share.
double run(const Program& p, const double* args, const Context& context, int component,
           int depth) {
    const RegisterCode& rc = p.lowered.get(p);
    if (rc.frame <= 32) return run_in<32>(rc, p, args, context, component, depth);
    if (rc.frame <= 128) return run_in<128>(rc, p, args, context, component, depth);
    return run_in<kMaxFrame>(rc, p, args, context, component, depth);
}

}  // namespace

const RegisterCode& LoweredCode::get(const Program& program) const {
    if (const RegisterCode* c = code_.load(std::memory_order_acquire)) return *c;
    const RegisterCode* made = new RegisterCode(lower(program));
    const RegisterCode* expected = nullptr;
    if (code_.compare_exchange_strong(expected, made, std::memory_order_acq_rel)) return *made;
    delete made;
    return *expected;
}

void LoweredCode::reset() { delete code_.exchange(nullptr); }

double evaluate(const Program& program, std::span<const double> args, const Context& context,
                int component) {
    return run(program, args.data(), context, component, 0);
}

}  // namespace lumen::fn

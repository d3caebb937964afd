// Math built-ins with POV-Ray 3.7's domain rules. Probed with `povray` (3.7.0.10) by
// `#declare V = EXPR; #debug str(V, 0, 10)`:
//   sqrt(x), x < 0 (even -1e-30)   Parse Error "sqrt of negative number"      (sqrt(-0) = -0)
//   ln(x), log(x), x <= 0 (and -0)  Parse Error "ln/log of negative number"    (ln(1e-300) fine)
//   atan2(a, b), |a|,|b| <= 1e-10   Parse Error "Domain error in atan2!"       (atan2(0, 1.1e-10) = 0)
//   pow(0, 0) (also -0)             Parse Error "Domain error."                (pow(0, 1e-30) = 0)
//   acos(x), asin(x), |x| > 1       Parse Warning "Domain error in acos.", x clamped to +-1
//                                   (acos(2) = 0, acos(-2) = pi, asin(2) = pi/2); NaN passes
//   x / 0 (any x, also 0/0, -1/0)   Parse Warning "Divide by zero.", per zero component, and the
//                                   result is +inf (-(1/0) = -inf: the sign is not the numerator's)
//   pow(0, -1), pow(-8, 1/3), mod(1, 0), exp(1000), acosh(0.5), atanh(1), 1e300*1e300, 1e400,
//   val("nan")                      no message: IEEE inf / nan
//   div(a, b), int(x)               (int) of the quotient / x: out of 32-bit range (div by 0,
//                                   int(1e10)) gives -2147483648
// Inside a function { } body (POV's function VM) nothing is checked: sqrt(-1) is nan, 1/0 inf,
// acos(2) nan, ln(0) -inf. lumen follows each of these, and adds a warning wherever POV-Ray lets
// an inf or nan appear silently (Evaluator::call_builtin, apply_binary), so none reaches the
// scene unannounced.
#include <algorithm>
#include <cmath>

#include "interp/builtin_table.hpp"
#include "interp/conversions.hpp"

namespace lumen::interp {
namespace {

constexpr double kPi = 3.14159265358979323846;

Builtin unary(double (*f)(double)) {
    return {1, 1, false, [f](Evaluator&, const ast::Node& c, Args& a) {
                return Value{f(to_float(a[0])), c.loc};
            }};
}

Builtin binary(double (*f)(double, double)) {
    return {2, 2, false, [f](Evaluator&, const ast::Node& c, Args& a) {
                return Value{f(to_float(a[0]), to_float(a[1])), c.loc};
            }};
}

// A function with a domain the parser enforces: `check` may throw or warn and returns the
// argument to use; inside a function body (POV's VM) the argument goes to `f` unchecked.
using Check = double (*)(Evaluator&, const ast::Node& call, const Value& arg, double x);
Builtin checked(double (*f)(double), Check check) {
    return {1, 1, false, [f, check](Evaluator& ev, const ast::Node& c, Args& a) {
                double x = to_float(a[0]);
                if (!ev.in_function_body()) x = check(ev, c, a[0], x);
                return Value{f(x), c.loc};
            }};
}

double positive_only(Evaluator&, const ast::Node& c, const Value& arg, double x) {
    if (x <= 0) throw LumenError(arg.loc, c.text + " of zero or a negative number (" + number_text(x) + ")");
    return x;
}

double clamp_to_unit(Evaluator& ev, const ast::Node& c, const Value& arg, double x) {
    if (!(x > 1 || x < -1)) return x;
    const double clamped = x > 1 ? 1 : -1;
    ev.warn(arg.loc, "domain error in " + c.text + ": " + number_text(x) + " is outside -1..1, " +
                         number_text(clamped) + " used instead (as POV-Ray does)");
    return clamped;
}

// POV's (int) conversion: truncation, and -2147483648 for anything outside the 32-bit range
// (what the x86 conversion gives, and so what POV-Ray prints).
double pov_int(double x) {
    if (!(x > -2147483649.0 && x < 2147483648.0)) return -2147483648.0;
    return std::trunc(x);
}

}  // namespace

void add_math_builtins(BuiltinTable& t) {
    t["abs"] = unary([](double a) { return std::fabs(a); });
    t["acos"] = checked([](double a) { return std::acos(a); }, clamp_to_unit);
    t["acosh"] = unary([](double a) { return std::acosh(a); });
    t["asin"] = checked([](double a) { return std::asin(a); }, clamp_to_unit);
    t["asinh"] = unary([](double a) { return std::asinh(a); });
    t["atan"] = unary([](double a) { return std::atan(a); });
    t["atanh"] = unary([](double a) { return std::atanh(a); });
    t["ceil"] = unary([](double a) { return std::ceil(a); });
    t["cos"] = unary([](double a) { return std::cos(a); });
    t["cosh"] = unary([](double a) { return std::cosh(a); });
    t["degrees"] = unary([](double a) { return a * 180.0 / kPi; });
    t["exp"] = unary([](double a) { return std::exp(a); });
    t["floor"] = unary([](double a) { return std::floor(a); });
    t["int"] = unary(pov_int);
    t["ln"] = checked([](double a) { return std::log(a); }, positive_only);
    t["log"] = checked([](double a) { return std::log10(a); }, positive_only);
    t["radians"] = unary([](double a) { return a * kPi / 180.0; });
    t["sin"] = unary([](double a) { return std::sin(a); });
    t["sinh"] = unary([](double a) { return std::sinh(a); });
    t["sqrt"] = checked([](double a) { return std::sqrt(a); },
                        [](Evaluator&, const ast::Node&, const Value& arg, double x) {
                            if (x < 0) throw LumenError(arg.loc, "sqrt of a negative number (" + number_text(x) + ")");
                            return x;
                        });
    t["tan"] = unary([](double a) { return std::tan(a); });
    t["tanh"] = unary([](double a) { return std::tanh(a); });
    t["atan2"] = {2, 2, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                      const double y = to_float(a[0]), x = to_float(a[1]);
                      if (!ev.in_function_body() && std::fabs(y) <= kEpsilon && std::fabs(x) <= kEpsilon)
                          throw LumenError(c.loc, "atan2(" + number_text(y) + ", " + number_text(x) +
                                                      ") is undefined: both arguments are within 1e-10 of 0");
                      return Value{std::atan2(y, x), c.loc};
                  }};
    t["div"] = {2, 2, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                    const double n = to_float(a[0]), d = to_float(a[1]);
                    if (d == 0 && !ev.in_function_body())
                        ev.warn(a[1].loc, "div() by zero gives -2147483648 (as in POV-Ray)");
                    return Value{pov_int(n / d), c.loc};
                }};
    t["mod"] = binary([](double a, double b) { return std::fmod(a, b); });
    t["pow"] = {2, 2, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                    const double b = to_float(a[0]), e = to_float(a[1]);
                    if (b == 0 && e == 0 && !ev.in_function_body())
                        throw LumenError(c.loc, "pow(0, 0) is undefined");
                    return Value{std::pow(b, e), c.loc};
                }};
    auto bitwise = [](long long (*op)(long long, long long)) {
        return Builtin{2, -1, false, [op](Evaluator&, const ast::Node& c, Args& a) {
                           long long acc = to_integer(a[0]);
                           for (size_t i = 1; i < a.size(); ++i) acc = op(acc, to_integer(a[i]));
                           return Value{static_cast<double>(acc), c.loc};
                       }};
    };
    t["bitwise_and"] = bitwise([](long long a, long long b) { return a & b; });
    t["bitwise_or"] = bitwise([](long long a, long long b) { return a | b; });
    t["bitwise_xor"] = bitwise([](long long a, long long b) { return a ^ b; });
    auto extreme = [](bool want_max) {
        return Builtin{1, -1, false, [want_max](Evaluator&, const ast::Node& c, Args& a) {
                           double r = to_float(a[0]);
                           for (size_t i = 1; i < a.size(); ++i)
                               r = want_max ? std::max(r, to_float(a[i])) : std::min(r, to_float(a[i]));
                           return Value{r, c.loc};
                       }};
    };
    t["min"] = extreme(false);
    t["max"] = extreme(true);
}

}  // namespace lumen::interp

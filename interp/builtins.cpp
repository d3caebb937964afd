// Built-in constants and functions (math, vector, string, array and random functions).
// Results were checked against POV-Ray 3.7 (see eval_builtins_test.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <unordered_map>

#include "interp/builtin_table.hpp"
#include "interp/conversions.hpp"
#include "noise/noise.hpp"

namespace lumen::interp {

namespace {

constexpr double kPi = 3.14159265358979323846;

Value vec(std::vector<double> c, SourceLoc loc) { return Value{VecN{std::move(c)}, loc}; }

}  // namespace

std::optional<Value> Evaluator::builtin_constant(const std::string& n, SourceLoc loc) const {
    static const std::unordered_map<std::string, std::vector<double>> fixed = {
        {"pi", {kPi}}, {"tau", {2 * kPi}}, {"true", {1}}, {"yes", {1}}, {"on", {1}},
        {"false", {0}}, {"no", {0}}, {"off", {0}},
        {"x", {1, 0, 0}}, {"y", {0, 1, 0}}, {"z", {0, 0, 1}}, {"t", {0, 0, 0, 1}},
        {"u", {1, 0}}, {"v", {0, 1}},
    };
    if (auto it = fixed.find(n); it != fixed.end()) {
        if (it->second.size() == 1) return Value{it->second[0], loc};
        return vec(it->second, loc);
    }
    const InterpOptions& o = options_;
    std::optional<double> f;
    if (n == "clock") f = static_cast<float>(o.clock);  // the clock is a 32-bit float
    else if (n == "clock_delta") f = six_digits(o.clock_delta);
    else if (n == "initial_clock") f = six_digits(o.initial_clock);
    else if (n == "final_clock") f = six_digits(o.final_clock);
    else if (n == "clock_on") f = o.clock_on ? 1 : 0;
    else if (n == "initial_frame") f = o.initial_frame;
    else if (n == "final_frame") f = o.final_frame;
    else if (n == "frame_number") f = o.frame_number;
    else if (n == "image_width") f = o.image_width;
    else if (n == "image_height") f = o.image_height;
    // Before any #version, `version` reads 3.7 while the scene is judged as 3.62 (legacy):
    // so an include's `#declare T = version; #version 3.5; ... #version T;` gives a scene
    // without #version the 3.7 rules, gamma included, as in POV-Ray.
    else if (n == "version") f = ctx.version_given ? ctx.language_version : 3.7;
    if (f) return Value{*f, loc};
    return std::nullopt;
}

// ---- string formatting --------------------------------------------------------------------

std::string format_float(double f, int width, int precision) {
    if (precision < 0) precision = 6;
    precision = std::min(precision, 100);  // POV-Ray prints as many as asked (25 checked)
    width = std::clamp(width, -64, 64);
    const char* fmt = width < 0 ? "%0*.*f" : "%*.*f";
    int w = std::abs(width);
    int n = std::snprintf(nullptr, 0, fmt, w, precision, f);
    std::string out(static_cast<size_t>(std::max(n, 0)), '\0');
    std::snprintf(out.data(), out.size() + 1, fmt, w, precision, f);
    return out;
}

namespace {

std::string utf8(long code) {
    std::string s;
    auto c = static_cast<unsigned long>(code);
    if (c < 0x80) {
        s += static_cast<char>(c);
    } else if (c < 0x800) {
        s += static_cast<char>(0xC0 | (c >> 6));
        s += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        s += static_cast<char>(0xE0 | ((c >> 12) & 0x0F));
        s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (c & 0x3F));
    }
    return s;
}

// Rotations in degrees about x, then y, then z (right-hand rule in POV's left-handed space:
// rotate x*90 takes +y to +z), checked against POV-Ray's vrotate.
glm::dvec3 rotate_xyz(glm::dvec3 p, const glm::dvec3& deg) {
    const double r[3] = {deg.x * kPi / 180, deg.y * kPi / 180, deg.z * kPi / 180};
    double c = std::cos(r[0]), s = std::sin(r[0]);
    p = {p.x, c * p.y - s * p.z, s * p.y + c * p.z};
    c = std::cos(r[1]), s = std::sin(r[1]);
    p = {c * p.x + s * p.z, p.y, -s * p.x + c * p.z};
    c = std::cos(r[2]), s = std::sin(r[2]);
    return {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
}

glm::dvec3 axis_rotate(const glm::dvec3& p, glm::dvec3 axis, double deg) {
    double len = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
    if (len == 0) return p;
    axis /= len;
    double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
    glm::dvec3 k_x_p{axis.y * p.z - axis.z * p.y, axis.z * p.x - axis.x * p.z,
                     axis.x * p.y - axis.y * p.x};
    double k_dot_p = axis.x * p.x + axis.y * p.y + axis.z * p.z;
    return p * c + k_x_p * s + axis * (k_dot_p * (1 - c));
}


double dot(const glm::dvec3& a, const glm::dvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

const std::string& str_arg(const Args& a, size_t i) { return to_string_value(a[i]); }

const BuiltinTable& builtin_table();

}  // namespace

bool Evaluator::is_builtin_function(const std::string& name) { return builtin_table().count(name) > 0; }

Value Evaluator::call_builtin(const ast::Node& call) {
    static const char* const unsupported[] = {"eval_pigment"};
    for (const char* u : unsupported)
        if (call.text == u) throw LumenError(call.loc, std::string("'") + u + "' is not supported");
    auto it = builtin_table().find(call.text);
    if (it == builtin_table().end()) {
        throw LumenError(call.loc, "undeclared identifier '" + call.text + "'",
                         did_you_mean(call.text, suggestion_words()));
    }
    const Builtin& b = it->second;
    int n = static_cast<int>(call.children.size());
    if (n < b.min_args || (b.max_args >= 0 && n > b.max_args)) {
        std::string want = b.min_args == b.max_args ? std::to_string(b.min_args)
                           : b.max_args < 0 ? "at least " + std::to_string(b.min_args)
                                            : std::to_string(b.min_args) + " to " + std::to_string(b.max_args);
        throw LumenError(call.loc, "'" + call.text + "' takes " + want + " argument(s), found " + std::to_string(n));
    }
    Args args;
    if (!b.lazy)
        for (const auto& c : call.children) args.push_back(eval(*c));
    Value result = b.fn(*this, call, args);
    // POV-Ray lets some results overflow or go undefined silently (math_builtins.cpp): say so
    // where an inf or nan first appears. Lazy built-ins (select, sum, prod) pass on values
    // whose own expressions were checked.
    if (!b.lazy && !all_finite(result) && std::all_of(args.begin(), args.end(), all_finite))
        warn(call.loc, "'" + call.text + "' gives " + non_finite_text(result) + " here");
    return result;
}

// Random streams: seed(n) starts a stream and returns its number; rand(stream) steps a
// 32-bit linear congruential generator. This matches POV-Ray 3.7's sequence.
double Evaluator::new_rand_stream(const Value& seed) {
    rand_streams_.push_back(static_cast<uint32_t>(to_integer(seed)));
    return static_cast<double>(rand_streams_.size() - 1);
}

double Evaluator::next_rand(const Value& stream) {
    double s = to_float(stream);
    if (!(s >= 0) || s >= static_cast<double>(rand_streams_.size()))
        throw LumenError(stream.loc, "rand() needs a stream made by seed()");
    uint32_t& state = rand_streams_[static_cast<size_t>(s)];
    state = state * 1812433253u + 12345u;
    return state / 4294967295.0;
}

// sum(I, from, to, expr) / prod(...): expr evaluated with I bound to each integer step.
Value Evaluator::fold_range(const ast::Node& call, bool product) {
    const ast::Node& var = *call.children[0];
    if (var.kind != ast::Kind::Ident) throw LumenError(var.loc, "expected an identifier");
    double from = eval_float(*call.children[1]), to = eval_float(*call.children[2]);
    double acc = product ? 1 : 0;
    FrameGuard frame(symbols);
    long long iterations = 0;
    for (double i = from; i <= to + kEpsilon; i += 1) {
        loop_limit(iterations, call, product ? "prod()" : "sum()");
        symbols.local(var.text, Value{i, var.loc});
        double term = eval_float(*call.children[3]);
        acc = product ? acc * term : acc + term;
    }
    return Value{acc, call.loc};
}

bool Evaluator::is_defined(const ast::Node& target) {
    if (target.kind == ast::Kind::Ident) return symbols.find(target.text) != nullptr;
    if (target.kind == ast::Kind::Index) {
        const ast::Node& base = *target.children.at(0);
        if (base.kind == ast::Kind::Ident && !symbols.find(base.text)) return false;
        try {
            ArraySlot slot = array_slot(target);
            return slot.array->elems[slot.index].has_value();
        } catch (const LumenError&) {
            return false;  // out of range or not an array
        }
    }
    throw LumenError(target.loc, "expected an identifier");
}

namespace {

const BuiltinTable& builtin_table() {
    static const BuiltinTable table = [] {
        BuiltinTable t;
        add_math_builtins(t);
        add_object_builtins(t);
        t["select"] = {3, 4, true, [](Evaluator& ev, const ast::Node& c, Args&) {
                           double s = ev.eval_float(*c.children[0]);
                           size_t pick = c.children.size() == 3 ? (s < 0 ? 1 : 2)
                                                                : (s < 0 ? 1 : s == 0 ? 2 : 3);
                           return ev.eval(*c.children[pick]);
                       }};
        t["seed"] = {1, 1, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                         return Value{ev.new_rand_stream(a[0]), c.loc};
                     }};
        t["rand"] = {1, 1, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                         return Value{ev.next_rand(a[0]), c.loc};
                     }};
        t["sum"] = {4, 4, true, [](Evaluator& ev, const ast::Node& c, Args&) { return ev.fold_range(c, false); }};
        t["prod"] = {4, 4, true, [](Evaluator& ev, const ast::Node& c, Args&) { return ev.fold_range(c, true); }};
        t["defined"] = {1, 1, true, [](Evaluator& ev, const ast::Node& c, Args&) {
                            return Value{double(ev.is_defined(*c.children[0])), c.loc};
                        }};
        // ---- vectors
        t["vdot"] = {2, 2, false, [](Evaluator&, const ast::Node& c, Args& a) {
                         return Value{dot(to_vec3(a[0]), to_vec3(a[1])), c.loc};
                     }};
        t["vcross"] = {2, 2, false, [](Evaluator&, const ast::Node& c, Args& a) {
                           glm::dvec3 p = to_vec3(a[0]), q = to_vec3(a[1]);
                           return vec3_value({p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x}, c.loc);
                       }};
        t["vlength"] = {1, 1, false, [](Evaluator&, const ast::Node& c, Args& a) {
                            // A float is promoted to <f, f, f>: vlength(1) is sqrt(3) (POV).
                            std::vector<double> v = components(a[0]);
                            if (v.size() == 1) v.assign(3, v[0]);
                            double s = 0;
                            for (double x : v) s += x * x;
                            return Value{std::sqrt(s), c.loc};
                        }};
        // vturbulence(Lambda, Omega, Octaves, P): POV's DTurbulence at P, lambda and omega
        // rounded to float and the octaves truncated and clamped to 1..10 (as POV-Ray does).
        t["vturbulence"] = {4, 4, false, [](Evaluator&, const ast::Node& c, Args& a) {
                                scene::TurbulenceParams params;
                                params.lambda = static_cast<float>(to_float(a[0]));
                                params.omega = static_cast<float>(to_float(a[1]));
                                params.octaves = int(std::clamp(to_float(a[2]), 1.0, 10.0));
                                return vec3_value(noise::dturbulence(to_vec3(a[3]), params), c.loc);
                            }};
        t["vnormalize"] = {1, 1, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                               glm::dvec3 p = to_vec3(a[0]);
                               double len = std::sqrt(dot(p, p));
                               if (len == 0) {
                                   ev.warn(c.loc, "normalizing a zero-length vector");
                                   return vec3_value({0, 0, 0}, c.loc);
                               }
                               return vec3_value(p / len, c.loc);
                           }};
        t["vrotate"] = {2, 2, false, [](Evaluator&, const ast::Node& c, Args& a) {
                            return vec3_value(rotate_xyz(to_vec3(a[0]), to_vec3(a[1])), c.loc);
                        }};
        t["vaxis_rotate"] = {3, 3, false, [](Evaluator&, const ast::Node& c, Args& a) {
                                 return vec3_value(axis_rotate(to_vec3(a[0]), to_vec3(a[1]), to_float(a[2])), c.loc);
                             }};
        // ---- strings
        t["asc"] = {1, 1, false, [](Evaluator&, const ast::Node& c, Args& a) {
                        const std::string& s = str_arg(a, 0);
                        return Value{s.empty() ? 0.0 : double(static_cast<unsigned char>(s[0])), c.loc};
                    }};
        t["chr"] = {1, 1, false, [](Evaluator&, const ast::Node& c, Args& a) {
                        double n = to_float(a[0]);
                        if (!(n >= 0 && n < 65536)) throw LumenError(a[0].loc, "chr() needs a code from 0 to 65535");
                        return Value{utf8(static_cast<long>(n)), c.loc};
                    }};
        t["concat"] = {1, -1, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                           size_t length = 0;
                           for (size_t i = 0; i < a.size(); ++i) length += str_arg(a, i).size();
                           ev.budget.string_built(length, c.loc);  // before it is built
                           std::string s;
                           s.reserve(length);
                           for (size_t i = 0; i < a.size(); ++i) s += str_arg(a, i);
                           return Value{s, c.loc};
                       }};
        t["str"] = {3, 3, false, [](Evaluator&, const ast::Node& c, Args& a) {
                        return Value{format_float(to_float(a[0]), to_int(a[1]), to_int(a[2])), c.loc};
                    }};
        t["vstr"] = {5, 5, false, [](Evaluator&, const ast::Node& c, Args& a) {
                         int n = to_int(a[0]);
                         if (n < 1 || n > 5) throw LumenError(a[0].loc, "vstr() needs 1 to 5 components");
                         std::vector<double> v = to_vector(a[1], static_cast<size_t>(n)).c;
                         const std::string& sep = str_arg(a, 2);
                         int width = to_int(a[3]), precision = to_int(a[4]);
                         std::string s;
                         for (int i = 0; i < n; ++i) s += (i ? sep : "") + format_float(v[i], width, precision);
                         return Value{s, c.loc};
                     }};
        t["strcmp"] = {2, 2, false, [](Evaluator&, const ast::Node& c, Args& a) {
                           int r = str_arg(a, 0).compare(str_arg(a, 1));
                           return Value{double(r < 0 ? -1 : r > 0 ? 1 : 0), c.loc};
                       }};
        t["strlen"] = {1, 1, false, [](Evaluator&, const ast::Node& c, Args& a) {
                           return Value{double(str_arg(a, 0).size()), c.loc};
                       }};
        auto recase = [](int (*f)(int)) {
            return Builtin{1, 1, false, [f](Evaluator&, const ast::Node& c, Args& a) {
                               std::string s = str_arg(a, 0);
                               for (char& ch : s) ch = static_cast<char>(f(static_cast<unsigned char>(ch)));
                               return Value{s, c.loc};
                           }};
        };
        t["strlwr"] = recase([](int ch) { return std::tolower(ch); });
        t["strupr"] = recase([](int ch) { return std::toupper(ch); });
        t["substr"] = {3, 3, false, [](Evaluator&, const ast::Node& c, Args& a) {
                           const std::string& s = str_arg(a, 0);
                           double pos = to_float(a[1]), len = to_float(a[2]);
                           if (!(pos >= 1) || !(len >= 0) || pos + len - 1 > double(s.size()) + kEpsilon)
                               throw LumenError(c.loc, "substr() range is outside the string (length " +
                                                           std::to_string(s.size()) + ")");
                           return Value{s.substr(size_t(pos) - 1, size_t(len)), c.loc};
                       }};
        t["val"] = {1, 1, false, [](Evaluator&, const ast::Node& c, Args& a) {
                        return Value{std::strtod(str_arg(a, 0).c_str(), nullptr), c.loc};
                    }};
        t["file_exists"] = {1, 1, false, [](Evaluator& ev, const ast::Node& c, Args& a) {
                                return Value{double(!ev.find_include(str_arg(a, 0)).empty()), c.loc};
                            }};
        // ---- arrays
        auto array_arg = [](const Value& v) -> const ArrayValue& {
            if (!v.is<std::shared_ptr<ArrayValue>>()) type_error(v, "an array");
            return *v.as<std::shared_ptr<ArrayValue>>();
        };
        t["dimensions"] = {1, 1, false, [array_arg](Evaluator&, const ast::Node& c, Args& a) {
                               return Value{double(array_arg(a[0]).dims.size()), c.loc};
                           }};
        t["dimension_size"] = {2, 2, false, [array_arg](Evaluator&, const ast::Node& c, Args& a) {
                                   const ArrayValue& arr = array_arg(a[0]);
                                   int d = to_int(a[1]);
                                   if (d < 1 || size_t(d) > arr.dims.size())
                                       throw LumenError(a[1].loc, "the array has no dimension " + std::to_string(d));
                                   return Value{double(arr.dims[size_t(d) - 1]), c.loc};
                               }};
        return t;
    }();
    return table;
}

}  // namespace

}  // namespace lumen::interp

#include "interp/conversions.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "base/diagnostics.hpp"

namespace lumen::interp {

void type_error(const Value& v, const char* expected) {
    const char* found = v.type_name();
    const char* article = std::string_view("aeiou").find(found[0]) != std::string_view::npos ? "an" : "a";
    throw LumenError(v.loc, std::string("expected ") + expected + ", found " + article + " " + found);
}

Value vec3_value(const glm::dvec3& v, SourceLoc loc) { return Value{VecN{{v.x, v.y, v.z}}, loc}; }

void unsupported_error(const scene::Unsupported& u) {
    throw LumenError(u.loc, "'" + u.feature + "' is not supported yet");
}

bool is_numeric(const Value& v) {
    return v.is<double>() || v.is<VecN>() || v.is<scene::Colour>();
}

double to_float(const Value& v) {
    if (!v.is<double>()) type_error(v, "a float");
    return v.as<double>();
}

bool to_bool(const Value& v) { return std::fabs(to_float(v)) > kEpsilon; }

int to_int(const Value& v) {
    double d = to_float(v);
    if (!std::isfinite(d) || std::fabs(d) > 2e9) throw LumenError(v.loc, "integer value out of range");
    return static_cast<int>(d);
}

long long to_integer(const Value& v) {
    double d = to_float(v);
    if (!std::isfinite(d) || std::fabs(d) > 9e18) throw LumenError(v.loc, "integer value out of range");
    return static_cast<long long>(d);
}

std::string number_text(double f) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", f);
    return buf;
}

std::vector<double> components(const Value& v) {
    if (v.is<double>()) return {v.as<double>()};
    if (v.is<VecN>()) return v.as<VecN>().c;
    if (v.is<scene::Colour>()) {
        const auto& c = v.as<scene::Colour>();
        return {c.r, c.g, c.b, c.f, c.t};
    }
    type_error(v, "a float, vector or colour");
}

VecN to_vector(const Value& v, size_t n) {
    if (v.is<double>()) return VecN{std::vector<double>(n, v.as<double>())};
    if (!v.is<VecN>() && !v.is<scene::Colour>()) type_error(v, "a vector");
    std::vector<double> c = components(v);
    c.resize(n, 0.0);
    return VecN{std::move(c)};
}

glm::dvec3 to_vec3(const Value& v) { return to_vector(v, 3).xyz(); }

scene::Colour colour_from(const std::vector<double>& c) {
    auto at = [&](size_t i) { return i < c.size() ? c[i] : 0.0; };
    return {at(0), at(1), at(2), at(3), at(4)};
}

scene::Colour to_colour(const Value& v) {
    if (v.is<scene::Colour>()) return v.as<scene::Colour>();
    if (v.is<double>()) {
        double d = v.as<double>();
        return {d, d, d, d, d};
    }
    if (v.is<VecN>()) return colour_from(v.as<VecN>().c);
    type_error(v, "a colour");
}

const std::string& to_string_value(const Value& v) {
    if (!v.is<std::string>()) type_error(v, "a string");
    return v.as<std::string>();
}

double six_digits(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(static_cast<float>(x)));
    return std::strtod(buf, nullptr);
}

double grey(const scene::Colour& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }

bool all_finite(const Value& v) {
    if (v.is<double>()) return std::isfinite(v.as<double>());
    if (!v.is<VecN>() && !v.is<scene::Colour>()) return true;
    for (double c : components(v))
        if (!std::isfinite(c)) return false;
    return true;
}

std::string non_finite_text(const Value& v) {
    std::vector<double> c = is_numeric(v) ? components(v) : std::vector<double>{};
    for (double x : c) {
        if (std::isfinite(x)) continue;
        const std::string word = std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
        return v.is<double>() ? word : std::string("a ") + v.type_name() + " with " + word;
    }
    return "a finite value";
}

}  // namespace lumen::interp

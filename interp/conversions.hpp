// Conversions between runtime values, with POV-Ray's promotion rules:
// a float stands for a vector with every component equal to it, or for a colour with all five
// channels equal to it; a vector becomes a colour by padding with zero channels.
#pragma once
#include <string>

#include "interp/value.hpp"

namespace lumen::interp {

constexpr double kEpsilon = 1e-10;  // POV's EPSILON: truth and equality tolerance

// True for float, vector and colour values.
bool is_numeric(const Value& v);

// Each throws LumenError at v.loc ("expected a float, found a string").
double to_float(const Value& v);
bool to_bool(const Value& v);            // |x| > EPSILON
VecN to_vector(const Value& v, size_t n);  // float -> n copies; vectors padded with 0 / cut
glm::dvec3 to_vec3(const Value& v);
// A 3-component vector value.
Value vec3_value(const glm::dvec3& v, SourceLoc loc);
scene::Colour to_colour(const Value& v);
const std::string& to_string_value(const Value& v);
int to_int(const Value& v);  // truncates toward zero, like POV's int()
long long to_integer(const Value& v);  // same, for the 64-bit range (bitwise functions, seeds)
std::string number_text(double f);     // "3", "-1", "2.5", "1e+30" for messages

// True when every number in `v` (float, vector or colour) is finite; true for other values.
bool all_finite(const Value& v);
// "inf", "-inf" or "nan" for a float; "a vector with nan" and the like otherwise.
std::string non_finite_text(const Value& v);

// The numeric components of a float/vector/colour (1, n or 5 of them).
std::vector<double> components(const Value& v);
scene::Colour colour_from(const std::vector<double>& c);  // missing channels are 0

// POV's grey value of a colour: 0.297 r + 0.589 g + 0.114 b.
double grey(const scene::Colour& c);

// POV's str(F, L, P): printf "%L.Pf"; L < 0 pads with zeros, P < 0 means 6 digits.
std::string format_float(double f, int width, int precision);

// Declare= values and the animation identifiers pass through a 32-bit float printed with six
// significant digits (POV-Ray 3.7's rules): 0.123456789 -> 0.123457.
double six_digits(double x);

[[noreturn]] void type_error(const Value& v, const char* expected);
// "'isosurface' is not supported yet" at the feature's location.
[[noreturn]] void unsupported_error(const scene::Unsupported& u);

}  // namespace lumen::interp

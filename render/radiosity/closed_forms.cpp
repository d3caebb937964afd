// The catalogue formulas, written out once.
#include "render/radiosity/closed_forms.hpp"

#include <cmath>
#include <numbers>

namespace lumen::render::radiosity::closed_form {

using std::atan;
using std::log;
using std::sqrt;
constexpr double pi = std::numbers::pi;

double point_to_coaxial_disc(double h, double r) { return r * r / (h * h + r * r); }

double coaxial_discs(double r1, double r2, double h) {
    const double R1 = r1 / h, R2 = r2 / h;
    const double X = 1 + (1 + R2 * R2) / (R1 * R1);
    return 0.5 * (X - sqrt(X * X - 4 * (R2 / R1) * (R2 / R1)));
}

double parallel_rectangles(double a, double b, double c) {
    const double X = a / c, Y = b / c;
    const double X2 = X * X, Y2 = Y * Y;
    const double braces = 0.5 * log((1 + X2) * (1 + Y2) / (1 + X2 + Y2)) +
                          X * sqrt(1 + Y2) * atan(X / sqrt(1 + Y2)) +
                          Y * sqrt(1 + X2) * atan(Y / sqrt(1 + X2)) - X * atan(X) - Y * atan(Y);
    return 2 / (pi * X * Y) * braces;
}

double perpendicular_rectangles(double l, double w, double h) {
    const double W = w / l, H = h / l;
    const double W2 = W * W, H2 = H * H, S = W2 + H2;
    const double log_term = log((1 + W2) * (1 + H2) / (1 + S)) +
                            W2 * log(W2 * (1 + S) / ((1 + W2) * S)) +
                            H2 * log(H2 * (1 + S) / ((1 + H2) * S));
    return 1 / (pi * W) *
           (W * atan(1 / W) + H * atan(1 / H) - sqrt(S) * atan(1 / sqrt(S)) + 0.25 * log_term);
}

double point_below_rectangle_corner(double a, double b, double c) {
    const double A = a / c, B = b / c;
    return 1 / (2 * pi) *
           (A / sqrt(1 + A * A) * atan(B / sqrt(1 + A * A)) +
            B / sqrt(1 + B * B) * atan(A / sqrt(1 + B * B)));
}

}  // namespace lumen::render::radiosity::closed_form

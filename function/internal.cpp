// POV-Ray 3.7's internal functions, each computed in POV's order of operations (its grouping of
// products and sums, its min/max argument order) so that the values agree to the last bit or
// nearly. The formulas keep POV's quirks: they are what scenes written for POV were tuned on.
#include "function/internal.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include <glm/vec3.hpp>

#include "function/internal_noise.hpp"

namespace lumen::fn {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * kPi;
constexpr double kPiOver180 = kPi / 180;

// Tube counts beyond which POV would loop for minutes; lumen draws at most this many.
constexpr int kMaxTubes = 10000;

// One call's arguments. The point is a copy: several functions move it before use, as POV's
// do on its stack.
// References into the VM's stack, not copies: the VM has just stored the arguments there one
// by one, and a wide copy of them would wait on those stores.
struct Args {
    const double& x;
    const double& y;
    const double& z;
    const double* p;  // the parameters after x, y, z
    int scene_generator;
};
using Function = double (*)(const Args&);
// A copy for the few functions that move x off the axis.
struct OwnArgs {
    double x, y, z;
    const double* p;
    int scene_generator;
};

// Most surfaces' value: the field strength times r, limited to [-10, 10]. The argument order
// of min and max is POV's; it makes a NaN product 10.
double field(double strength, double r) {
    return std::min(10.0, std::max(strength * r, -10.0));
}

// The _2d curves' (and algbr_cyl's) surface-of-revolution switch. sw > 0 revolves the (x, y)
// curve about y at distance off, tilted by ang degrees; otherwise z is ignored (the curve is
// extruded along z).
struct Plane {
    double x, y, x2, y2;
};
Plane sor(const Args& a, double sw, double off, double ang) {
    Plane q{a.x, a.y, a.x * a.x, a.y * a.y};
    if (sw > 0) {
        const double r = std::sqrt(q.x2 + a.z * a.z) - off;
        const double th = ang * kPiOver180;
        if (th != 0) {
            q.x = r * std::cos(th) - a.y * std::sin(th);
            q.y = r * std::sin(th) + a.y * std::cos(th);
        } else {
            q.x = r;
        }
        q.x2 = q.x * q.x;
        q.y2 = q.y * q.y;
    }
    return q;
}

// The cross sections of helix1 and helix2 (spiral's differs in its last power): 1 a circle,
// 0 a square, otherwise a superellipse of exponent 2/cs.
double cross_section(double u, double v, double cs) {
    if (cs == 1) return std::sqrt(u * u + v * v);
    if (cs != 0) {
        const double e = 2. / cs;
        return std::pow(std::pow(std::fabs(u), e) + std::pow(std::fabs(v), e), cs * .5);
    }
    return std::max(std::fabs(u), std::fabs(v));
}

// The three axis-stretched gaussians of cross_ellipsoids, flange_cover, isect_ellipsoids and
// spikes.
struct Gaussians {
    double e1, e2, e3;
};
Gaussians gaussians(double x2, double y2, double z2, double e, double k) {
    return {std::exp(-(x2 * e + y2 * e + z2) * k), std::exp(-(x2 * e + y2 + z2 * e) * k),
            std::exp(-(x2 + y2 * e + z2 * e) * k)};
}

double algbr_cyl1(const Args& a) {
    const Plane q = sor(a, a.p[2], a.p[3], a.p[4]);
    const double r = -(q.x2 * std::fabs(q.x) - q.x2 + q.y2);
    return -std::min(a.p[1], std::max(a.p[0] * r, -a.p[1]));
}
double algbr_cyl2(const Args& a) {
    const auto [X, Y, x2, y2] = sor(a, a.p[2], a.p[3], a.p[4]);
    const double r = -(2 * x2 * x2 - 3 * x2 * Y + y2 - 2 * y2 * Y + y2 * y2);
    return std::min(a.p[1], std::max(a.p[0] * r, -a.p[1]));
}
double algbr_cyl3(const Args& a) {
    const auto [X, Y, x2, y2] = sor(a, a.p[2], a.p[3], a.p[4]);
    const double r = -(x2 * x2 + x2 * y2 - 2 * x2 * Y - X * y2 + y2);
    return std::min(a.p[1], std::max(a.p[0] * r, -a.p[1]));
}
double algbr_cyl4(const Args& a) {
    const auto [X, Y, x2, y2] = sor(a, a.p[2], a.p[3], a.p[4]);
    const double r = -(x2 * x2 + y2 * y2 + 2 * x2 * y2 + 3 * x2 * Y - y2 * Y);
    return std::min(a.p[1], std::max(a.p[0] * r, -a.p[1]));
}
double bicorn(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z, s = a.p[1] * a.p[1];
    const double q = x2 + z2 + 2 * a.p[1] * a.y - s;
    return field(a.p[0], y2 * (s - (x2 + z2)) - q * q);
}
double bifolia(const Args& a) {
    const double x2 = a.x * a.x, z2 = a.z * a.z, s = x2 + a.y * a.y + z2;
    return field(a.p[0], -(s * s - a.p[1] * (x2 + z2) * a.y));
}
double blob(const Args& a) {
    const double y2 = a.y * a.y, z2 = a.z * a.z, h = a.p[0] * 0.5;
    double r1 = ((a.x + h) * (a.x + h) + y2 + z2) * a.p[2] * a.p[2];
    if (r1 > 1.) r1 = 1.;  // not std::min: a NaN stays NaN, as in POV
    double r2 = ((a.x - h) * (a.x - h) + y2 + z2) * a.p[4] * a.p[4];
    if (r2 > 1.) r2 = 1.;
    return -(a.p[1] * (1. - r1) * (1. - r1) + a.p[3] * (1. - r2) * (1. - r2));
}
double blob2(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z, d = a.x - a.p[0];
    const double r = std::exp(-(x2 + y2 + z2) * a.p[1]) + std::exp(-(d * d + y2 + z2) * a.p[1]);
    return a.p[3] - r * a.p[2];
}
double boy_surface(const Args& a) {
    const double x = a.x, y = a.y, z = a.z, x2 = x * x, y2 = y * y, z2 = z * z;
    const double w = 1 - z, h = x2 + y2, s2 = std::sqrt(2.0);
    const double r =
        a.p[1] * (64 * w * w * w * z2 * z - 48 * w * w * z2 * (3 * x2 + 3 * y2 + 2 * z2) +
                  12 * w * z * (27 * h * h - 24 * z2 * h + 36 * s2 * y * z * (y2 - 3 * x2) +
                                4 * z2 * z2) +
                  (9 * x2 + 9 * y2 - 2 * z2) *
                      (-81 * h * h - 72 * z2 * h + 108 * s2 * x * z * (x2 - 3 * y2) + 4 * z2 * z2));
    return field(a.p[0], r);
}
double comma(const Args& in) {
    OwnArgs a{in.x, in.y, in.z, in.p, in.scene_generator};
    // POV moves x off the axis before the atan2 (and keeps it moved for the rest).
    if (a.x == 0 && a.z == 0) a.x = 0.0001;
    const double s = a.p[0], th = std::atan2(a.z, a.x);
    const double rho = std::sqrt((a.x + s * 0.25) * (a.x + s * 0.25) + a.z * a.z);
    double t = std::cos(th * 0.5) * s * 0.5 -
               std::sqrt((rho - s * 0.75) * (rho - s * 0.75) + a.y * a.y);
    t = std::min(a.z, t);
    const double u =
        s * 0.5 - std::sqrt((a.x - s * 0.5) * (a.x - s * 0.5) + a.z * a.z + a.y * a.y);
    return -std::max(t, u);
}
double cross_ellipsoids(const Args& a) {
    const Gaussians g = gaussians(a.x * a.x, a.y * a.y, a.z * a.z, a.p[0], a.p[1]);
    return a.p[3] - std::max(std::max(g.e1, g.e2), g.e3) * a.p[2];
}
double crossed_trough(const Args& a) { return field(a.p[0], a.x * a.x * a.z * a.z - a.y); }
double cubic_saddle(const Args& a) {
    return field(a.p[0], -(a.x * a.x * a.x - a.y * a.y * a.y - a.z));
}
// Also f_odd (43): POV's two polynomials differ only in writing 2*x2*y2 as 2*y2*x2.
double cushion(const Args& a) {
    const double z = a.z, x2 = a.x * a.x, y2 = a.y * a.y, z2 = z * z;
    return field(a.p[0], z2 * x2 - z2 * z2 - 2 * z * x2 + 2 * z2 * z + x2 - z2 -
                             (x2 - z) * (x2 - z) - y2 * y2 - 2 * x2 * y2 - y2 * z2 +
                             2 * y2 * z + y2);
}
double devils_curve(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0],
                 -(x2 * x2 + 2 * x2 * z2 - 0.36 * x2 - y2 * y2 + 0.25 * y2 + z2 * z2));
}
double devils_curve_2d(const Args& a) {
    const Plane q = sor(a, a.p[3], a.p[4], a.p[5]);
    return field(a.p[0],
                 -(q.x2 * (q.x2 - a.p[1] * a.p[1]) - q.y2 * (q.y2 - a.p[2] * a.p[2])));
}
double dupin_cyclid(const Args& a) {
    const double x = a.x, y = a.y, x2 = x * x, y2 = y * y, z2 = a.z * a.z;
    const double R = a.p[1], dx = a.p[3], dy = a.p[4];
    const double c = a.p[5] * a.p[5], A = a.p[2] * a.p[2], B = dy * dy;
    const double p = A - B - (dx + R) * (dx + R), q = A - B - (dx - R) * (dx - R);
    const double dx2 = dx * dx, R2 = R * R;
    const double r = -(p * q * (x2 * x2 + y2 * y2 + z2 * z2) +
                       2 * (p * q * (x2 * y2 + x2 * z2 + y2 * z2)) +
                       2 * c *
                           ((-B - dx2 + A + R2) * (2 * x * dx + 2 * y * dy - c) -
                            4 * dy * A * y) *
                           (x2 + y2 + z2) +
                       4 * c * c * (dx * x + dy * y) * (-c + dy * y + dx * x) +
                       4 * c * c * R2 * y2 + c * c * c * c);
    return field(a.p[0], r);
}
double ellipsoid(const Args& a) {
    // No "- 1": the surface is at the threshold the scene gives.
    return std::sqrt(a.x * a.x * a.p[0] * a.p[0] + a.y * a.y * a.p[1] * a.p[1] +
                     a.z * a.z * a.p[2] * a.p[2]);
}
double enneper(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    // POV replaces z (sign and all) near the plane z = 0, after squaring it.
    const double z = std::fabs(a.z) < 0.2 ? 0.2 : a.z;
    // POV's source writes 2/3, 1/4, 8/9 and 2/9 in integers: each is 0. The zero terms are
    // kept for their effect on infinities (0 * inf is NaN).
    const double r1 = (y2 - x2) / (2 * z) + 2 * z2 / 9 + 0.0;
    const double r2 = (y2 - x2) / (4 * z) - 0.0 * (x2 + y2 + 0.0 * z2) + 0.0;
    return field(a.p[0], -(r1 * r1 * r1 - 6 * r2 * r2));
}
double flange_cover(const Args& a) {
    const Gaussians g = gaussians(a.x * a.x, a.y * a.y, a.z * a.z, a.p[0], a.p[1]);
    return a.p[3] - (g.e1 + g.e2 + g.e3) * a.p[2];
}
double folium_surface(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0], (y2 + z2) * (1 + (a.p[2] - 4 * a.p[1]) * a.x) + x2 * (1 + a.p[2]));
}
double folium_surface_2d(const Args& a) {
    const Plane q = sor(a, a.p[3], a.p[4], a.p[5]);
    return field(a.p[0], -(q.y2 * (1 + (a.p[2] - 4 * a.p[1]) * q.x) + q.x2 * (1 + a.p[2])));
}
double glob(const Args& a) {
    const double x2 = a.x * a.x;
    return field(a.p[0], 0.5 * x2 * x2 * a.x + 0.5 * x2 * x2 - (a.y * a.y + a.z * a.z));
}
double heart(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z, q = 2 * x2 + y2 + z2 - 1;
    return field(a.p[0], -(q * q * q - 0.1 * x2 * z2 * a.z - y2 * z2 * a.z));
}
double helical_torus(const Args& in) {
    OwnArgs a{in.x, in.y, in.z, in.p, in.scene_generator};
    const double* p = a.p;
    double rho = std::sqrt(a.x * a.x + a.z * a.z);
    if (a.x == 0 && a.z == 0) a.x = 0.000001;  // as POV, after rho and before the atan2
    const double ph = std::atan2(a.x, a.z);
    const double d = std::sqrt((rho - p[0]) * (rho - p[0]) + a.y * a.y);
    double th = std::fmod(ph * p[1] + std::atan2(rho - p[0], a.y) * p[2], kTwoPi);
    if (th < 0) th += kTwoPi;
    const double groove = std::atan2((th - kPi) * p[8], d - p[5]);
    double c = std::cos(groove * p[7] + ph * p[9]) * p[3] + p[4];
    rho = p[4] + p[5] - p[0] - rho;
    th = th - kPi;
    c = c - std::min(std::sqrt((d - p[5]) * (d - p[5]) + th * th * p[6]), d + p[5]);
    return -std::max(rho, c);
}
double helix1(const Args& in) {
    OwnArgs a{in.x, in.y, in.z, in.p, in.scene_generator};
    const double* p = a.p;
    const double rho = std::sqrt(a.x * a.x + a.z * a.z);
    if (a.x == 0 && a.z == 0) a.x = 0.000001;
    double th = std::fmod(std::atan2(a.z, a.x) * p[0] + a.y * p[1] * p[0], kTwoPi);
    if (th < 0) th += kTwoPi;
    double Z = (th - kPi) / p[4] / (p[1] * p[0]);
    double X = rho - p[3];
    double q;
    if (p[5] == 1) {
        q = std::sqrt(X * X + Z * Z);
    } else {
        if (p[6] != 0) {
            const double c = std::cos(p[6] * kPiOver180), s = std::sin(p[6] * kPiOver180);
            const double u = X * c - Z * s;
            Z = X * s + Z * c;
            X = u;
        }
        q = cross_section(X, Z, p[5]);
    }
    return -p[2] + std::min(p[3] + rho, q);
}
double helix2(const Args& a) {
    const double* p = a.p;
    const double c = std::cos(a.y * p[1]), s = std::sin(a.y * p[1]);
    const double u = a.x - p[3] * c, w = a.z - p[3] * s;
    return cross_section(u * c + w * s, -u * s + w * c, p[5]) - p[2];
}
// hex_x and hex_y: the distances to a hexagonal grid's edges, in the x-y plane.
struct Hex {
    double a, b;
    bool near;  // atan2(b, a) < pi/6
};
Hex hex(Args in) {
    const double h = std::sqrt(3.0) / 2;
    double a = std::fabs(std::fmod(std::fabs(in.x), std::sqrt(3.0)) - h);
    double b = std::fabs(std::fmod(std::fabs(in.y), 3) - 1.5);
    const double a2 = h - a, b2 = 1.5 - b;
    if (a * a + b * b > a2 * a2 + b2 * b2) a = a2, b = b2;
    return {a, b, std::atan2(b, a) < kPi / 6};
}
double hex_x(const Args& a) {
    const Hex h = hex(a);
    return h.near ? h.a : std::cos(kPi / 3) * h.a + std::sin(kPi / 3) * h.b;
}
double hex_y(const Args& a) {
    const Hex h = hex(a);
    return h.near ? h.b : std::fabs(-std::sin(kPi / 3) * h.a + std::cos(kPi / 3) * h.b);
}
double hunt_surface(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    const double q = x2 + y2 + z2 - 13, w = 3 * x2 + y2 - 4 * z2 - 12;
    return field(a.p[0], -(4 * q * q * q + 27 * w * w));
}
double hyperbolic_torus(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    const double A = a.p[1] * a.p[1], B = a.p[2] * a.p[2];
    return field(a.p[0], -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z2 - 2 * (A + B) * x2 + y2 * y2 -
                           2 * y2 * z2 + 2 * (A - B) * y2 + z2 * z2 + 2 * (A + B) * z2 +
                           (A - B) * (A - B)));
}
double isect_ellipsoids(const Args& a) {
    const Gaussians g = gaussians(a.x * a.x, a.y * a.y, a.z * a.z, a.p[0], a.p[1]);
    return a.p[3] - std::min(std::min(g.e1, g.e2), g.e3) * a.p[2];
}
double kampyle_of_eudoxus(const Args& a) {
    const double x2 = a.x * a.x, b = a.p[2];
    return field(a.p[0],
                 -((a.y * a.y + a.z * a.z) - b * b * x2 * x2 + b * b * a.p[1] * a.p[1] * x2));
}
double kampyle_of_eudoxus_2d(const Args& a) {
    const Plane q = sor(a, a.p[3], a.p[4], a.p[5]);
    const double b = a.p[2];
    // a*b where the 3-D version has a*a: POV's source has it so.
    return field(a.p[0], -(q.y2 - b * b * q.x2 * q.x2 + b * b * a.p[1] * b * q.x2));
}
double klein_bottle(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z, s = x2 + y2 + z2;
    const double m = s - 2 * a.y - 1;
    return field(a.p[0], -((s + 2 * a.y - 1) * (m * m - 8 * z2) + 16 * a.x * a.z * m));
}
double kummer_surface_v1(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0], -(x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2 - x2 * y2 - x2 * z2 -
                           y2 * z2 + 1));
}
double kummer_surface_v2(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0], -(x2 * x2 + y2 * y2 + z2 * z2 + a.p[1] * (x2 + y2 + z2) +
                           a.p[2] * (x2 * y2 + x2 * z2 + y2 * z2) + a.p[3] * a.x * a.y * a.z - 1));
}
double lemniscate_of_gerono(const Args& a) {
    const double x2 = a.x * a.x;
    return field(a.p[0], -(x2 * x2 - x2 + a.y * a.y + a.z * a.z));
}
double lemniscate_of_gerono_2d(const Args& a) {
    const Plane q = sor(a, a.p[3], a.p[4], a.p[5]);
    const double b = a.p[2];
    return field(a.p[0], -(q.y2 - b * b * a.p[1] * a.p[1] * q.x2 + b * b * q.x2 * q.x2));
}
double mesh1(const Args& a) {
    const double* p = a.p;
    // The distance across one set of threads: u folded into [0, 2d), less d, scaled by k.
    auto across = [&](double u, double d) {
        double r = std::fmod(u, d * 2);
        if (r < 0) r += d * 2;
        return std::fabs(r - d) * p[2];
    };
    auto dist = [](double h, double v) { return -std::sqrt(v * v + h * h); };
    const double cz = std::cos(a.z * (kPi / p[1])), cx = std::cos(a.x * (kPi / p[0]));
    double t = dist(across(a.x, p[0]), (a.y - cz * p[3]) * p[4]);
    t = std::max(dist(across(a.x - p[0], p[0]), (a.y + cz * p[3]) * p[4]), t);
    t = std::max(dist(across(a.z, p[1]), (a.y + cx * p[3]) * p[4]), t);
    return -std::max(dist(across(a.z - p[1], p[1]), (a.y - cx * p[3]) * p[4]), t);
}
double mitre(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0], -(4 * x2 * (x2 + y2 + z2) - y2 * (1 - y2 - z2)));
}
double nodal_cubic(const Args& a) {
    return field(a.p[0], -(a.y * a.y * a.y + a.z * a.z * a.z - 6 * a.y * a.z));
}
double ovals_of_cassini(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z, R = a.p[1];
    const double q = x2 + y2 + z2 + R * R;
    return field(a.p[0], -(q * q - a.p[3] * R * R * (x2 + z2) - a.p[2] * a.p[2]));
}
double paraboloid(const Args& a) { return field(a.p[0], -(a.x * a.x - a.y + a.z * a.z)); }
double parabolic_torus(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z, z = a.z;
    const double A = a.p[1] * a.p[1], B = a.p[2] * a.p[2];
    return field(a.p[0], -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z - (A + B) * x2 + y2 * y2 -
                           2 * y2 * z + (A - B) * y2 + z2 + (A + B) * z + (A - B) * (A - B)));
}
double ph(const Args& a) { return std::atan2(std::sqrt(a.x * a.x + a.z * a.z), a.y); }
double pillow(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0], x2 * x2 + y2 * y2 + z2 * z2 - (x2 + y2 + z2));
}
double piriform(const Args& a) {
    const double x2 = a.x * a.x;
    return -field(a.p[0], -((x2 * x2 - x2 * a.x) + a.y * a.y + a.z * a.z));
}
double piriform_2d(const Args& a) {
    const Plane q = sor(a, a.p[4], a.p[5], a.p[6]);
    const double f = a.p[3];
    return field(a.p[0], -(q.y * q.y - a.p[1] * f * f * q.x2 * q.x - a.p[2] * f * f * q.x2 * q.x2));
}
double poly4(const Args& a) {
    const double* c = a.p;
    const double y = a.y, y2 = y * y;
    double q = c[0] + c[1] * y + c[2] * y2 + c[3] * y2 * y + c[4] * y2 * y2;
    if (q < -5.) q = -5.;
    return -q + std::sqrt(a.x * a.x + a.z * a.z);
}
double polytubes(const Args& a) {
    const double* p = a.p;
    const double y = a.y, y2 = y * y;
    const double rho = p[1] + p[2] * y + p[3] * y2 + p[4] * y2 * y + p[5] * y2 * y2;
    const int n = std::min(detail::to_int(p[0]), kMaxTubes);
    double r = -10000;  // so 10000 without tubes
    for (int i = 0; i < n; ++i) {
        const double u = a.x - rho * std::sin(2 * kPi / p[0] * i);
        const double w = a.z - rho * std::cos(2 * kPi / p[0] * i);
        r = std::max(r, -std::sqrt(u * u + w * w));
    }
    return -r;
}
double quantum(const Args& in) {
    OwnArgs a{in.x, in.y, in.z, in.p, in.scene_generator};
    if (a.x == 0 && a.z == 0) a.x = 1e-6;  // here before everything, unlike helix1
    const double rho = std::sqrt(a.x * a.x + a.z * a.z);
    const double c = std::cos(std::atan2(rho, a.y));
    const double r = std::sqrt(rho * rho + a.y * a.y) * 2.;
    const double q = r * r * std::exp(-r * 0.33333333) * (3. * c * c - 1);
    return (q * q - 12.0) * (-0.1);
}
double quartic_paraboloid(const Args& a) {
    const double x2 = a.x * a.x, z2 = a.z * a.z;
    return field(a.p[0], -(x2 * x2 + z2 * z2 - a.y));
}
double quartic_saddle(const Args& a) {
    const double x2 = a.x * a.x, z2 = a.z * a.z;
    return field(a.p[0], -(x2 * x2 - z2 * z2 - a.y));
}
double quartic_cylinder(const Args& a) {
    const double x2 = a.x * a.x, z2 = a.z * a.z, b = a.p[2];
    return field(a.p[0], -((x2 + z2) * a.y * a.y + b * b * (x2 + z2) - b * b * a.p[1] * a.p[1]));
}
double r(const Args& a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
double rounded_box(const Args& a) {
    const double R = a.p[0];
    // POV's form of max(0, |p| - (s - R)) per axis.
    auto out = [R](double c, double s) {
        const double hi = s - R, lo = R - s;
        return std::max(c > lo ? 0 : lo - c, c < hi ? 0 : c - hi);
    };
    const double x = out(a.x, a.p[1]), y = out(a.y, a.p[2]), z = out(a.z, a.p[3]);
    return -R + std::sqrt(x * x + y * y + z * z) - 1e-6;
}
double sphere(const Args& a) { return -a.p[0] + std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
double spikes(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    const Gaussians g = gaussians(x2, y2, z2, a.p[0], a.p[1]);
    const double r = std::exp(-(x2 + y2 + z2) * a.p[3]) * a.p[4] - g.e1 - g.e2 - g.e3;
    return -r * a.p[2];
}
double spikes_2d(const Args& a) {
    const double* p = a.p;
    return -(p[0] * std::cos(p[1] * a.x) * std::cos(p[2] * a.z) *
                 std::exp(-p[3] * (a.x * a.x + a.z * a.z)) -
             a.y);
}
double spiral(const Args& in) {
    OwnArgs a{in.x, in.y, in.z, in.p, in.scene_generator};
    const double* p = a.p;
    double rho = std::sqrt(a.x * a.x + a.z * a.z);
    if (a.x == 0 && a.z == 0) a.x = 0.000001;  // also in the distance below, as in POV
    rho = rho + p[0] * std::atan2(a.z, a.x) / kTwoPi;
    const double w = std::fmod(rho, p[0]) - p[0] * 0.5;
    double q;
    if (p[5] == 1) {
        q = std::sqrt(w * w + a.y * a.y);
    } else if (p[5] != 0) {
        const double e = 2 / p[5];  // POV raises to 1/e here, not to cs/2 as helix1 does
        q = std::pow(std::pow(std::fabs(w), e) + std::pow(std::fabs(a.y), e), 1. / e);
    } else {
        q = std::max(std::fabs(w), std::fabs(a.y));
    }
    const double R = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    return -std::min(p[2] - R, p[1] - std::min(q, R));
}
double steiners_roman(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0], -(x2 * y2 + x2 * z2 + y2 * z2 + a.x * a.y * a.z));
}
double strophoid(const Args& a) {
    const double x2 = a.x * a.x, c = a.p[3] * a.p[3];
    return field(a.p[0],
                 -((a.p[2] - a.x) * (a.y * a.y + a.z * a.z) - c * a.p[1] * x2 - c * x2 * a.x));
}
double strophoid_2d(const Args& a) {
    const Plane q = sor(a, a.p[4], a.p[5], a.p[6]);
    const double c = a.p[3] * a.p[3];
    return field(a.p[0], -((a.p[2] - q.x) * q.y2 - c * a.p[1] * q.x2 - c * q.x2 * q.x));
}
double superellipsoid(const Args& a) {
    const double e = 2 / a.p[0], n = 1 / a.p[1];
    return 1 - std::pow(std::pow(std::pow(std::fabs(a.x), e) + std::pow(std::fabs(a.y), e),
                                 a.p[0] * n) +
                            std::pow(std::fabs(a.z), 2 * n),
                        a.p[1] * .5);
}
double th(const Args& a) { return std::atan2(a.x, a.z); }
double torus(const Args& a) {
    const double u = std::sqrt(a.x * a.x + a.z * a.z) - a.p[0];
    return -a.p[1] + std::sqrt(u * u + a.y * a.y);
}
double torus2(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    const double A = a.p[1] * a.p[1], B = a.p[2] * a.p[2];
    return field(a.p[0], -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 + 2 * y2 * z2 -
                           2 * (A + B) * x2 + 2 * (A - B) * y2 - 2 * (A + B) * z2 +
                           (A - B) * (A - B)));
}
double torus_gumdrop(const Args& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    return field(a.p[0], -(4 * (x2 * x2 + (y2 + z2) * (y2 + z2)) + 17 * x2 * (y2 + z2) -
                           20 * (x2 + y2 + z2) + 17));
}
double umbrella(const Args& a) { return field(a.p[0], -(a.x * a.x - a.y * a.z * a.z)); }
double witch_of_agnesi(const Args& a) {
    return field(a.p[0], -(a.p[1] * (a.y - 1) + (a.x * a.x + a.z * a.z) * a.y));
}
double witch_of_agnesi_2d(const Args& a) {
    const Plane q = sor(a, a.p[3], a.p[4], a.p[5]);
    return field(a.p[0], -(a.p[1] * a.p[1] * q.y + q.x2 * q.y - a.p[2]));
}
double noise3d(const Args& a) { return detail::noise3d({a.x, a.y, a.z}, a.scene_generator); }
// POV's trap for `function { pattern { ... } }`; without a pattern behind it, 0.
double pattern(const Args&) { return 0.0; }
double noise_generator(const Args& a) { return detail::noise_generator({a.x, a.y, a.z}, a.p); }
double hetero_mf(const Args& a) { return detail::hetero_mf({a.x, a.y, a.z}, a.p); }
double ridge(const Args& a) { return detail::ridge({a.x, a.y, a.z}, a.p); }
double ridged_mf(const Args& a) { return detail::ridged_mf({a.x, a.y, a.z}, a.p); }

struct Entry {
    InternalInfo info;
    Function function;
};

// In functions.inc's order, which is the order of N.
constexpr Entry kTable[] = {
    {{"algbr_cyl1", 5}, algbr_cyl1},
    {{"algbr_cyl2", 5}, algbr_cyl2},
    {{"algbr_cyl3", 5}, algbr_cyl3},
    {{"algbr_cyl4", 5}, algbr_cyl4},
    {{"bicorn", 2}, bicorn},
    {{"bifolia", 2}, bifolia},
    {{"blob", 5}, blob},
    {{"blob2", 4}, blob2},
    {{"boy_surface", 2}, boy_surface},
    {{"comma", 1}, comma},
    {{"cross_ellipsoids", 4}, cross_ellipsoids},
    {{"crossed_trough", 1}, crossed_trough},
    {{"cubic_saddle", 1}, cubic_saddle},
    {{"cushion", 1}, cushion},
    {{"devils_curve", 1}, devils_curve},
    {{"devils_curve_2d", 6}, devils_curve_2d},
    {{"dupin_cyclid", 6}, dupin_cyclid},
    {{"ellipsoid", 3}, ellipsoid},
    {{"enneper", 1}, enneper},
    {{"flange_cover", 4}, flange_cover},
    {{"folium_surface", 3}, folium_surface},
    {{"folium_surface_2d", 6}, folium_surface_2d},
    {{"glob", 1}, glob},
    {{"heart", 1}, heart},
    {{"helical_torus", 10}, helical_torus},
    {{"helix1", 7}, helix1},
    {{"helix2", 7}, helix2},
    {{"hex_x", 1}, hex_x},
    {{"hex_y", 1}, hex_y},
    {{"hetero_mf", 6}, hetero_mf},
    {{"hunt_surface", 1}, hunt_surface},
    {{"hyperbolic_torus", 3}, hyperbolic_torus},
    {{"isect_ellipsoids", 4}, isect_ellipsoids},
    {{"kampyle_of_eudoxus", 3}, kampyle_of_eudoxus},
    {{"kampyle_of_eudoxus_2d", 6}, kampyle_of_eudoxus_2d},
    {{"klein_bottle", 1}, klein_bottle},
    {{"kummer_surface_v1", 1}, kummer_surface_v1},
    {{"kummer_surface_v2", 4}, kummer_surface_v2},
    {{"lemniscate_of_gerono", 1}, lemniscate_of_gerono},
    {{"lemniscate_of_gerono_2d", 6}, lemniscate_of_gerono_2d},
    {{"mesh1", 5}, mesh1},
    {{"mitre", 1}, mitre},
    {{"nodal_cubic", 1}, nodal_cubic},
    {{"odd", 1}, cushion},
    {{"ovals_of_cassini", 4}, ovals_of_cassini},
    {{"paraboloid", 1}, paraboloid},
    {{"parabolic_torus", 3}, parabolic_torus},
    {{"ph", 0}, ph},
    {{"pillow", 1}, pillow},
    {{"piriform", 1}, piriform},
    {{"piriform_2d", 7}, piriform_2d},
    {{"poly4", 5}, poly4},
    {{"polytubes", 6}, polytubes},
    {{"quantum", 1}, quantum},
    {{"quartic_paraboloid", 1}, quartic_paraboloid},
    {{"quartic_saddle", 1}, quartic_saddle},
    {{"quartic_cylinder", 3}, quartic_cylinder},
    {{"r", 0}, r},
    {{"ridge", 6}, ridge},
    {{"ridged_mf", 6}, ridged_mf},
    {{"rounded_box", 4}, rounded_box},
    {{"sphere", 1}, sphere},
    {{"spikes", 5}, spikes},
    {{"spikes_2d", 4}, spikes_2d},
    {{"spiral", 6}, spiral},
    {{"steiners_roman", 1}, steiners_roman},
    {{"strophoid", 4}, strophoid},
    {{"strophoid_2d", 7}, strophoid_2d},
    {{"superellipsoid", 2}, superellipsoid},
    {{"th", 0}, th},
    {{"torus", 2}, torus},
    {{"torus2", 3}, torus2},
    {{"torus_gumdrop", 1}, torus_gumdrop},
    {{"umbrella", 1}, umbrella},
    {{"witch_of_agnesi", 2}, witch_of_agnesi},
    {{"witch_of_agnesi_2d", 6}, witch_of_agnesi_2d},
    {{"noise3d", 0}, noise3d},
    {{"pattern", 0}, pattern},  // not declared in functions.inc
    {{"noise_generator", 1}, noise_generator},
};
static_assert(std::size(kTable) == kInternalCount);

}  // namespace

const InternalInfo& internal_info(int n) { return kTable[n].info; }

double internal(int n, const double* args, int noise_generator) {
    if (n < 0 || n >= kInternalCount) return 0.0;
    return kTable[n].function({args[0], args[1], args[2], args + 3, noise_generator});
}

}  // namespace lumen::fn

// spline { [linear_spline | quadratic_spline | cubic_spline | natural_spline] t0, V0, t1, V1, ... }
// as POV-Ray 3.7 evaluates it: entries kept sorted by t, values of 2 to 5 components (a float
// is <v, v>), clamped outside the knots, each type's curve between them. Plain data, below the
// interpreter (S(t) in a scene) and the function VM (`function { spline { S } }`).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace lumen::fn {

enum class SplineType : uint8_t { Linear, Quadratic, Cubic, Natural };

struct Spline {
    struct Entry {
        double t;
        std::array<double, 5> v{};
    };
    SplineType type = SplineType::Linear;
    std::vector<Entry> entries;  // sorted by t
    int terms = 2;               // components of a value: the most any entry was given (2..5)
    std::vector<std::array<double, 5>> moments;  // the natural spline's, from prepare()

    // Adds an entry as POV-Ray does: a repeated t replaces the earlier value, but a repeat of
    // the largest t so far is dropped (POV-Ray's indexing).
    void add(double t, const std::array<double, 5>& v, int components);
    // Solves the natural spline's system once, so that at() allocates nothing (call it after
    // the last add).
    void prepare();
    // The value at t by `type` (at least one entry; `terms` components are meaningful).
    std::array<double, 5> at(double t, SplineType type) const;
    std::array<double, 5> at(double t) const { return at(t, type); }
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("type", s.type), f("terms", s.terms);
        for (const Entry& e : s.entries) f("t", e.t), f("v", e.v);
    }
};

}  // namespace lumen::fn

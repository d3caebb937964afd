// Tilings 25, 26 and 27 (Penrose pentagons, kites and darts, rhombs) against values read from
// povray 3.7's 16-bit renders: a 0.001-wide orthographic view of the plane y = 0 centred on each
// point, 1 × 1 pixel, -A, color_map [0 rgb 0] [1 rgb 1], assumed_gamma 1, File_Gamma 1. Points
// near and far from the origin (out to 1e9) and in every tile kind; POV's output rounds the
// value, so each is matched within half a step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "render/patterns/penrose.hpp"

namespace lumen::render {
namespace {

struct Read {
    int tiling;
    double x, z;
    int count;  // POV's output at (x, 0, z), of 65535
};

const Read kReads[] = {
    // pentagons (kinds 0, 1, 2), stars (3), boats (4) and diamonds (5), sixths of [0, 1]
    {25, 0.3, 0.2, 0},  // the kind-0 pentagon about the origin, flat
    {25, 1.7, -2.45, 10923},
    {25, -3.1, 4.05, 15418},
    {25, 5.55, 1.35, 10923},
    {25, 0.05, 1.31, 21845},  // a kind-2 pentagon's flat
    {25, 5.83, 0.3, 34375},   // a star
    {25, 3.4, 0.05, 43690},   // a boat's flat
    {25, -1.9, 0.02, 56375},  // a diamond
    {25, 1000.3, -77.7, 23769},
    {25, -731.21, 1203.9, 31328},
    {25, 123456.7, -98765.4, 31457},
    {25, 25000000.31, 11000000.2, 32520},
    {25, 1000000000.123, -299999999.23, 21845},
    // kites (kind 0, [0, 0.5]) and darts (kind 1, [0.5, 1])
    {26, 0.3, 0.2, 30644},
    {26, 1.7, -2.45, 60888},
    {26, -3.1, 4.05, 29661},
    {26, 5.55, 1.35, 15434},
    {26, 0.05, 1.31, 12579},
    {26, 0.52, 0.013, 0},  // a kite's flat, in the sun about the origin
    {26, -0.41, 0.77, 20035},
    {26, 1000.3, -77.7, 5447},
    {26, -731.21, 1203.9, 58845},
    {26, 123456.7, -98765.4, 35882},
    {26, 25000000.31, 11000000.2, 13708},
    {26, 1000000000.123, -299999999.23, 40164},
    // thick rhombs (kind 0) and thin rhombs (kind 1)
    {27, 0.3, 0.2, 10288},
    {27, 1.7, -2.45, 54705},
    {27, -3.1, 4.05, 23275},
    {27, 5.55, 1.35, 11543},
    {27, 0.05, 1.31, 50008},
    {27, 1.31, 0.013, 33059},  // a thin rhomb's middle, just above 0.5
    {27, 2.43, 0.05, 0},       // a thick rhomb's flat
    {27, 1000.3, -77.7, 14741},
    {27, -731.21, 1203.9, 27622},
    {27, 123456.7, -98765.4, 9962},
    {27, 25000000.31, 11000000.2, 23323},
    {27, 1000000000.123, -299999999.23, 21703},
};

TEST(Penrose, ValuesReadFromPovray) {
    for (const Read& r : kReads)
        EXPECT_NEAR(penrose_tiles(r.tiling, r.x, r.z) * 65535, r.count, 0.5 + 1e-6)
            << "tiling " << r.tiling << " at " << r.x << ", " << r.z;
}

// The layout is symmetric under turns by 72° about the origin and the mirror z -> -z (POV's
// tilings are built from a sun about the origin).
TEST(Penrose, FiveFoldSymmetryAboutTheOrigin) {
    const double t = 72 * 3.14159265358979323846 / 180;
    for (const int type : {25, 26, 27})
        for (double x = -5; x < 5; x += 0.37)
            for (double z = -5; z < 5; z += 0.41) {
                const double v = penrose_tiles(type, x, z);
                const double xr = x * std::cos(t) - z * std::sin(t);
                const double zr = x * std::sin(t) + z * std::cos(t);
                EXPECT_NEAR(penrose_tiles(type, xr, zr), v, 1e-9) << type << " " << x << " " << z;
                EXPECT_NEAR(penrose_tiles(type, x, -z), v, 1e-9) << type << " " << x << " " << z;
            }
}

// POV lifts the flats of every kind but the first 1e-6 above k/T, so a colour_map key at k/T
// falls below them (measured with keys 2e-5 wide); kind 0's flats stay at 0.
TEST(Penrose, FlatsClearTheKeys) {
    EXPECT_EQ(penrose_tiles(25, 0.3, 0.2), 0);
    EXPECT_NEAR(penrose_tiles(25, 0.05, 1.31), 2.0 / 6 + 1e-6, 1e-12);
    EXPECT_NEAR(penrose_tiles(25, 3.4, 0.05), 4.0 / 6 + 1e-6, 1e-12);
    EXPECT_NEAR(penrose_tiles(27, 1.309017, 0), 0.5 + 1e-6, 1e-12);  // a thin rhomb's middle
    EXPECT_EQ(penrose_tiles(27, 2.43, 0.05), 0);
    EXPECT_EQ(penrose_tiles(26, 0.52, 0.013), 0);
}

// Every kind shows up, values stay in [0, 1], and huge or non-finite inputs give finite values.
TEST(Penrose, KindsRangeAndFarPoints) {
    for (const int type : {25, 26, 27}) {
        const int kinds_of_type = type == 25 ? 6 : 2;
        std::set<int> kinds;
        for (double x = -6; x < 6; x += 0.0731)
            for (double z = -6; z < 6; z += 0.0677) {
                const double v = penrose_tiles(type, x, z);
                ASSERT_TRUE(v >= 0 && v <= 1) << type << " at " << x << ", " << z;
                kinds.insert(std::min(int(v * kinds_of_type), kinds_of_type - 1));
            }
        EXPECT_EQ(int(kinds.size()), kinds_of_type) << type;
        for (const double far :
             {1e7, -3.3e9, 1e15, 1e29, 1e31, 1e300, double(INFINITY), double(NAN)}) {
            const double v = penrose_tiles(type, far, -far / 3);
            EXPECT_TRUE(std::isfinite(v) && v >= 0 && v <= 1) << type << " at " << far;
        }
    }
    EXPECT_EQ(penrose_tiles(24, 0.3, 0.2), 0);
}

}  // namespace
}  // namespace lumen::render

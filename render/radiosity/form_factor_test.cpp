// Closed forms, Lambert's contour formula and its area average against the catalogue values.
#include <cmath>

#include <gtest/gtest.h>

#include "render/radiosity/closed_forms.hpp"
#include "render/radiosity/ff_matrix.hpp"
#include "render/radiosity/form_factor.hpp"
#include "render/radiosity/quadrature.hpp"
#include "render/radiosity/radiosity_test_util.hpp"

namespace lumen::render::radiosity {
namespace {

using namespace testing;
namespace cf = closed_form;

TEST(ClosedForms, CatalogueValues) {
    EXPECT_NEAR(cf::point_to_coaxial_disc(1, 1), 0.5, 1e-12);
    EXPECT_NEAR(cf::point_to_coaxial_disc(1, 0.5), 0.2, 1e-12);
    EXPECT_NEAR(cf::point_to_coaxial_disc(2, 1), 0.2, 1e-12);
    EXPECT_NEAR(cf::coaxial_discs(1, 1, 1), 0.381966, 1e-6);
    EXPECT_NEAR(cf::coaxial_discs(1, 1, 1), (3 - std::sqrt(5.0)) / 2, 1e-12);
    EXPECT_NEAR(cf::coaxial_discs(0.5, 1, 1), 0.468871, 1e-6);
    EXPECT_NEAR(cf::coaxial_discs(1, 1, 2), 0.171573, 1e-6);
    EXPECT_NEAR(cf::parallel_rectangles(1, 1, 1), 0.199825, 1e-6);
    EXPECT_NEAR(cf::parallel_rectangles(2, 1, 1), 0.285875, 1e-6);
    EXPECT_NEAR(cf::parallel_rectangles(1, 1, 0.5), 0.415253, 1e-6);
    EXPECT_NEAR(cf::parallel_rectangles(1, 1, 2), 0.068590, 1e-6);
    EXPECT_NEAR(cf::perpendicular_rectangles(1, 1, 1), 0.200044, 1e-6);
    EXPECT_NEAR(cf::perpendicular_rectangles(1, 1, 2), 0.232853, 1e-6);
    EXPECT_NEAR(cf::perpendicular_rectangles(1, 2, 1), 0.116426, 1e-6);
    EXPECT_NEAR(cf::perpendicular_rectangles(2, 1, 1), 0.240636, 1e-6);
    EXPECT_NEAR(cf::point_below_rectangle_corner(1, 1, 1), 0.138532, 1e-6);
}

TEST(ClosedForms, CubeRowSumAndReciprocityCrossCheck) {
    EXPECT_NEAR(cf::parallel_rectangles(1, 1, 1) + 4 * cf::perpendicular_rectangles(1, 1, 1), 1.0,
                1e-9);
    // 1·F(w=1 → h=2) = 2·F(w=2 → h=1)
    EXPECT_NEAR(cf::perpendicular_rectangles(1, 1, 2), 2 * cf::perpendicular_rectangles(1, 2, 1),
                1e-12);
}

TEST(Quadrature, GaussLegendreIntegratesPolynomialsExactly) {
    for (int order : {1, 2, 5, 12}) {
        const Rule r = gauss_legendre(order);
        for (int p = 0; p < 2 * order; ++p) {
            double s = 0;
            for (const auto& [x, w] : r) s += w * std::pow(x, p);
            EXPECT_NEAR(s, 1.0 / (p + 1), 1e-13) << "order " << order << " power " << p;
        }
    }
    double s = 0;
    for (const auto& [x, w] : graded_rule(4, 3)) s += w * std::sqrt(x);
    EXPECT_NEAR(s, 2.0 / 3.0, 1e-5);
}

TEST(Lambert, PointToDiscAsManyGon) {
    const glm::dvec3 up(0, 0, 1);
    // A 4096-gon's area differs from the disc's by 4e-7 relative.
    EXPECT_NEAR(point_to_polygon({0, 0, 0}, up, disc_polygon(1, 1, false, 4096)), 0.5, 1e-6);
    EXPECT_NEAR(point_to_polygon({0, 0, 0}, up, disc_polygon(0.5, 1, false, 4096)), 0.2, 1e-6);
    EXPECT_NEAR(point_to_polygon({0, 0, 0}, up, disc_polygon(1, 2, false, 4096)), 0.2, 1e-6);
    // The 256-gon of the notes: within its inscribed-area error.
    EXPECT_NEAR(point_to_polygon({0, 0, 0}, up, disc_polygon(1, 1, false, 256)), 0.5, 1e-4);
}

TEST(Lambert, CornerAndCentreValues) {
    const glm::dvec3 up(0, 0, 1);
    EXPECT_NEAR(point_to_polygon({0, 0, 0}, up, ceiling_rect(1, 1, 1)), 0.138532, 1e-6);
    EXPECT_NEAR(point_to_polygon({0.5, 0.5, 0}, up, ceiling_rect(1, 1, 1)), 0.239456, 1e-6);
    // Centre of the floor square to its perpendicular neighbour (the wall in y = 0).
    EXPECT_NEAR(point_to_polygon({0.5, 0.5, 0}, up, wall_rect(1, 1)), 0.190136, 1e-6);
    // Orientation of the target does not matter, only what is in front of the point.
    EXPECT_NEAR(point_to_polygon({0.5, 0.5, 0}, up, flipped(ceiling_rect(1, 1, 1))),
                point_to_polygon({0.5, 0.5, 0}, up, ceiling_rect(1, 1, 1)), 1e-15);
    EXPECT_EQ(point_to_polygon({0.5, 0.5, 0}, -up, ceiling_rect(1, 1, 1)), 0.0);
}

TEST(Lambert, PartlyBehindIsClipped) {
    // A wall crossing the point's tangent plane: only the upper half counts.
    const Patch wall = make_patch({{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}});
    const Patch upper = make_patch({{-1, 1, 0}, {1, 1, 0}, {1, 1, 1}, {-1, 1, 1}});
    const glm::dvec3 up(0, 0, 1);
    const double f = point_to_polygon({0, 0, 0}, up, wall);
    EXPECT_GT(f, 0.01);
    EXPECT_NEAR(f, point_to_polygon({0, 0, 0}, up, upper), 1e-12);
}

TEST(AreaToArea, ParallelAndPerpendicularSquares) {
    EXPECT_NEAR(patch_to_patch(floor_rect(1, 1), ceiling_rect(1, 1, 1)), 0.199825, 1e-6);
    EXPECT_NEAR(patch_to_patch(floor_rect(2, 1), ceiling_rect(2, 1, 1)), 0.285875, 1e-6);
    EXPECT_NEAR(patch_to_patch(floor_rect(1, 1), ceiling_rect(1, 1, 0.5)), 0.415253, 1e-6);
    EXPECT_NEAR(patch_to_patch(floor_rect(1, 1), ceiling_rect(1, 1, 2)), 0.068590, 1e-6);
    // Shared edge: log singularity, handled by the graded cells.
    EXPECT_NEAR(patch_to_patch(floor_rect(1, 1), wall_rect(1, 1)), 0.200044, 1e-6);
    EXPECT_NEAR(patch_to_patch(floor_rect(1, 1), wall_rect(1, 2)), 0.232853, 1e-6);
    EXPECT_NEAR(patch_to_patch(floor_rect(1, 2), wall_rect(1, 1)), 0.116426, 1e-6);
    EXPECT_NEAR(patch_to_patch(floor_rect(2, 1), wall_rect(2, 1)), 0.240636, 1e-6);
}

TEST(AreaToArea, CoaxialDiscs) {
    const QuadratureOptions q{4, 1};
    // 128-gons: the polygonisation error (about 4e-4 relative area) dominates.
    EXPECT_NEAR(patch_to_patch(disc_polygon(1, 0, true, 128), disc_polygon(1, 1, false, 128), q),
                0.381966, 1e-3);
    EXPECT_NEAR(
        patch_to_patch(disc_polygon(0.5, 0, true, 128), disc_polygon(1, 1, false, 128), q),
        0.468871, 1e-3);
}

TEST(AreaToArea, Reciprocity) {
    const Patch a = floor_rect(1, 1), b = wall_rect(1, 2);
    EXPECT_NEAR(a.area * patch_to_patch(a, b), b.area * patch_to_patch(b, a), 1e-6);
    EXPECT_NEAR(a.area * patch_to_patch(a, b), 0.232853, 1e-6);
}

TEST(AreaToArea, ClosedCubeRowSums) {
    const auto patches = unit_cube_inside(3);
    ASSERT_EQ(patches.size(), 54u);
    const auto F = analytic_matrix(patches, {4, 3});
    for (size_t i = 0; i < F.n; ++i) {
        EXPECT_NEAR(F.row_sum(i), 1.0, 1e-6) << "patch " << i;
        EXPECT_EQ(F(i, i), 0.0);
        for (size_t j = 0; j < F.n; ++j)
            EXPECT_NEAR(patches[i].area * F(i, j), patches[j].area * F(j, i), 1e-7);
    }
}

TEST(AreaToArea, DegenerateAndCoincidentPairsStayFinite) {
    const Patch square = floor_rect(1, 1);
    const Patch sliver = make_patch({{0, 0, 1}, {1, 0, 1}, {2, 0, 1}});  // collinear: zero area
    const Patch point = make_patch({{0.5, 0.5, 1}, {0.5, 0.5, 1}, {0.5, 0.5, 1}});
    const Patch coincident = flipped(square);  // z-fighting, facing the other way
    const Patch touching = make_patch({{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}});  // coplanar
    const Patch corner = make_patch({{1, 1, 0}, {1, 1, 1}, {1, 2, 1}, {1, 2, 0}});   // a vertex
    for (const Patch* p : {&sliver, &point, &coincident, &square, &touching, &corner}) {
        for (double f : {patch_to_patch(square, *p), patch_to_patch(*p, square),
                         point_to_polygon(square.vertices[1], square.normal, *p),
                         point_to_polygon({0.5, 0, 0}, square.normal, *p)}) {
            EXPECT_TRUE(std::isfinite(f));
            EXPECT_GE(f, 0.0);
            EXPECT_LE(f, 1.0);
        }
    }
    EXPECT_EQ(patch_to_patch(square, sliver), 0.0);
    EXPECT_EQ(patch_to_patch(square, coincident), 0.0);
    EXPECT_EQ(patch_to_patch(square, touching), 0.0);
    EXPECT_GT(patch_to_patch(square, corner), 0.0);
    EXPECT_TRUE(sliver.degenerate());
    EXPECT_TRUE(std::isfinite(sliver.normal.x + sliver.centroid.x));
}

}  // namespace
}  // namespace lumen::render::radiosity

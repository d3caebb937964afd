// Radiosity solvers: closed-form solutions (furnace, six-patch cube), agreement with LU,
// Jacobi as the Neumann series, progressive refinement, and the stability reports.
#include <cmath>

#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "render/radiosity/closed_forms.hpp"
#include "render/radiosity/radiosity_test_util.hpp"
#include "render/radiosity/solver.hpp"

namespace lumen::render::radiosity {
namespace {

using namespace testing;

std::vector<std::unique_ptr<Solver>> all_solvers() {
    std::vector<std::unique_ptr<Solver>> s;
    s.push_back(make_lu_solver());
    s.push_back(make_jacobi_solver());
    s.push_back(make_gauss_seidel_solver());
    s.push_back(make_gauss_seidel_solver(1.1));
    s.push_back(make_progressive_solver());
    return s;
}

double max_abs_difference(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double m = 0;
    for (size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(a[i][c] - b[i][c]));
    return m;
}

// Six patches of the unit cube with the exact catalogue form factors; patch 0 is the top.
// Order: top, bottom, then the four sides.
RadiositySystem six_patch_cube(double rho) {
    const double opp = closed_form::parallel_rectangles(1, 1, 1);
    const double adj = closed_form::perpendicular_rectangles(1, 1, 1);
    RadiositySystem s;
    s.F = FormFactorMatrix(6);
    const int opposite[6] = {1, 0, 3, 2, 5, 4};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            if (i != j) s.F(i, j) = j == opposite[i] ? opp : adj;
    s.rho.assign(6, glm::dvec3(rho));
    s.emission.assign(6, glm::dvec3(0));
    s.emission[0] = glm::dvec3(1);
    s.area.assign(6, 1.0);
    return s;
}

// The inside of a sphere (exact F_ij = A_j / A) with uniform ρ and E.
RadiositySystem furnace_sphere(double rho, double E) {
    scene::Object sphere;
    sphere.shape = scene::Sphere{{0, 0, 0}, 1};
    MeshOptions opt;
    opt.max_edge = 0.6;
    opt.inward = true;
    const auto patches = mesh_object(sphere, opt, {glm::dvec3(rho), glm::dvec3(E), 0});
    return make_system(patches, sphere_interior_matrix(patches));
}

TEST(Solvers, SixPatchCube) {
    struct Case { double rho, top, bottom, side; };
    for (const Case c : {Case{0.5, 1.090909, 0.181746, 0.181836},
                         Case{0.9, 2.372881, 1.525311, 1.525452}}) {
        const auto s = six_patch_cube(c.rho);
        for (auto& solver : all_solvers()) {
            const auto report = solve(*solver, s, {1e-12, 100000});
            ASSERT_EQ(report.status, SolveStatus::Converged) << solver->name() << report.message;
            const auto B = solver->radiosity();
            EXPECT_NEAR(B[0].x, c.top, 2e-6) << solver->name();
            EXPECT_NEAR(B[1].y, c.bottom, 2e-6) << solver->name();
            for (int k = 2; k < 6; ++k) EXPECT_NEAR(B[k].z, c.side, 2e-6) << solver->name();
            double power = 0;
            for (const auto& b : B) power += b.x;
            EXPECT_NEAR(power, 1 / (1 - c.rho), 1e-6);
        }
    }
}

TEST(Solvers, FurnaceSphere) {
    for (double rho : {0.5, 0.9, 0.99}) {
        const auto s = furnace_sphere(rho, 1.0);
        for (auto& solver : all_solvers()) {
            const auto report = solve(*solver, s, {1e-11, 200000});
            ASSERT_EQ(report.status, SolveStatus::Converged) << solver->name() << report.message;
            for (const auto& b : solver->radiosity())
                ASSERT_NEAR(b.y, 1 / (1 - rho), 1e-6 / (1 - rho)) << solver->name();
        }
    }
}

TEST(Solvers, FurnaceMeshedCubeEnergy) {
    const auto patches = unit_cube_inside(3);
    const auto F = analytic_matrix(patches, {4, 3});
    for (double rho : {0.5, 0.9, 0.99}) {
        auto s = make_system(patches, F);
        s.rho.assign(s.size(), glm::dvec3(rho));
        s.emission.assign(s.size(), glm::dvec3(1));
        auto lu = make_lu_solver();
        ASSERT_EQ(solve(*lu, s).status, SolveStatus::Converged);
        double power = 0;
        for (size_t i = 0; i < s.size(); ++i) power += s.area[i] * lu->radiosity()[i].x;
        // Row sums are 1 within 1e-6; ρ/(1−ρ)² amplifies that at ρ = 0.99.
        EXPECT_NEAR(power / 6, 1 / (1 - rho), 1e-6 * rho / ((1 - rho) * (1 - rho)) + 1e-9);
    }
}

// Sphere with non-uniform E and ρ: B_i = E_i + ρ_i Ē / (1 − ρ̄) when F_ij = A_j / A exactly;
// the tessellation's own (flat-facet) form factors approach it as the mesh is refined.
TEST(Solvers, NonUniformSphere) {
    auto sphere_patches = [](double edge) {
        scene::Object sphere;
        sphere.shape = scene::Sphere{{0, 0, 0}, 1};
        MeshOptions opt;
        opt.max_edge = edge;
        opt.inward = true;
        auto patches = mesh_object(sphere, opt, {glm::dvec3(0), glm::dvec3(0), 0});
        for (auto& p : patches) {
            p.rho = glm::dvec3(0.3 + 0.5 * (p.centroid.y > 0), 0.5, 0.8);
            p.emission = glm::dvec3(p.centroid.x > 0.5 ? 2.0 : 0.0);
        }
        return patches;
    };
    auto expected = [](const std::vector<Patch>& patches) {
        glm::dvec3 e(0), r(0);
        const double a = total_area(patches);
        for (const auto& p : patches) e += p.area * p.emission / a, r += p.area * p.rho / a;
        std::vector<glm::dvec3> B;
        for (const auto& p : patches) B.push_back(p.emission + p.rho * e / (1.0 - r));
        return B;
    };
    const auto coarse = sphere_patches(0.8);
    auto lu = make_lu_solver();
    ASSERT_EQ(solve(*lu, make_system(coarse, sphere_interior_matrix(coarse))).status,
              SolveStatus::Converged);
    EXPECT_LT(max_abs_difference(lu->radiosity(), expected(coarse)), 1e-12);
    // Tessellated: error against the formula shrinks with refinement.
    double previous = INFINITY;
    for (double edge : {0.8, 0.45}) {
        const auto patches = sphere_patches(edge);
        ASSERT_EQ(solve(*lu, make_system(patches, analytic_matrix(patches, {2, 1}))).status,
                  SolveStatus::Converged);
        const double err = max_abs_difference(lu->radiosity(), expected(patches));
        EXPECT_LT(err, previous) << "edge " << edge;
        previous = err;
    }
    EXPECT_LT(previous, 0.1);
}

// Open scenes balance emitted power against absorbed and escaping power.
TEST(Solvers, OpenBoxPowerBalance) {
    auto patches = unit_cube_inside(2);
    std::erase_if(patches, [](const Patch& p) { return p.centroid.z > 0.99; });  // no lid
    for (auto& p : patches) {
        p.rho = glm::dvec3(0.6, 0.3, 0.9);
        p.emission = glm::dvec3(p.centroid.z < 0.01 ? 1.0 : 0.0);
    }
    // The identity needs reciprocity to round-off; the quadrature gives it to about 1e-8.
    auto F = analytic_matrix(patches, {4, 2});
    symmetrise(F, patches);
    const auto s = make_system(patches, F);
    auto lu = make_lu_solver();
    ASSERT_EQ(solve(*lu, s).status, SolveStatus::Converged);
    const auto B = lu->radiosity();
    glm::dvec3 emitted(0), absorbed(0), escaped(0);
    for (size_t i = 0; i < s.size(); ++i) {
        glm::dvec3 G(0);
        for (size_t j = 0; j < s.size(); ++j) G += s.F(i, j) * B[j];
        emitted += s.area[i] * s.emission[i];
        absorbed += s.area[i] * (1.0 - s.rho[i]) * G;
        escaped += s.area[i] * B[i] * (1 - s.F.row_sum(i));
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(emitted[c], absorbed[c] + escaped[c], 1e-9);
    EXPECT_GT(escaped.x, 0.1);
}

TEST(Solvers, AllAgreeWithLu) {
    const auto patches = unit_cube_inside(3);
    auto s = make_system(patches, analytic_matrix(patches, {3, 1}));
    for (size_t i = 0; i < s.size(); ++i) {
        s.rho[i] = glm::dvec3(0.9, 0.5 + 0.005 * i, 0.2 * (i % 4));
        s.emission[i] = i % 7 == 0 ? glm::dvec3(1, 2, 3) : glm::dvec3(0);
    }
    auto lu = make_lu_solver();
    ASSERT_EQ(solve(*lu, s).status, SolveStatus::Converged);
    const auto ref = lu->radiosity();
    EXPECT_LT(lu->residual(), 1e-12);
    for (auto& solver : all_solvers()) {
        const auto report = solve(*solver, s, {1e-11, 1000000});
        ASSERT_EQ(report.status, SolveStatus::Converged) << solver->name() << report.message;
        const auto B = solver->radiosity();
        for (size_t i = 0; i < B.size(); ++i)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(B[i][c], ref[i][c], 1e-8) << solver->name();
    }
}

TEST(Solvers, JacobiSweepsAreNeumannPartialSums) {
    const auto patches = unit_cube_inside(2);
    auto s = make_system(patches, analytic_matrix(patches, {3, 1}));
    for (size_t i = 0; i < s.size(); ++i) {
        s.rho[i] = glm::dvec3(0.7, 0.3, 0.9);
        s.emission[i] = glm::dvec3(i == 0 ? 1.0 : 0.0, i == 5 ? 1.0 : 0.0, 0.1);
    }
    auto jacobi = make_jacobi_solver();
    jacobi->init(s);
    std::vector<glm::dvec3> term = s.emission, sum = s.emission;
    for (int k = 1; k <= 6; ++k) {
        std::vector<glm::dvec3> next(s.size(), glm::dvec3(0));  // next = ρ F term
        for (size_t i = 0; i < s.size(); ++i) {
            for (size_t j = 0; j < s.size(); ++j) next[i] += s.F(i, j) * term[j];
            next[i] *= s.rho[i];
        }
        term = next;
        for (size_t i = 0; i < s.size(); ++i) sum[i] += term[i];
        jacobi->step();
        const auto B = jacobi->radiosity();
        for (size_t i = 0; i < s.size(); ++i)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(B[i][c], sum[i][c], 1e-13) << "sweep " << k;
    }
    // One bounce from the six-patch cube by hand: B_bottom = ρ F_opp E_top.
    auto one = make_jacobi_solver();
    one->init(six_patch_cube(0.5));
    one->step();
    EXPECT_NEAR(one->radiosity()[1].x, 0.5 * closed_form::parallel_rectangles(1, 1, 1), 1e-15);
}

TEST(Solvers, ProgressiveShootsLightsFirstAndAmbientHelpsEarly) {
    const auto patches = unit_cube_inside(3);
    auto s = make_system(patches, analytic_matrix(patches, {3, 1}));
    for (size_t i = 0; i < s.size(); ++i) {
        s.rho[i] = glm::dvec3(0.9);
        s.emission[i] = glm::dvec3(i < 9 ? 1.0 : 0.0);  // one face emits
    }
    auto lu = make_lu_solver();
    solve(*lu, s);
    const auto ref = lu->radiosity();
    auto prog = make_progressive_solver();
    prog->init(s);
    for (size_t k = 0; k < s.size(); ++k) prog->step();
    double err_raw = 0, err_ambient = 0, total = 0;
    const auto raw = prog->radiosity(), shown = prog->display();
    for (size_t i = 0; i < s.size(); ++i) {
        err_raw += s.area[i] * std::abs(raw[i].x - ref[i].x);
        err_ambient += s.area[i] * std::abs(shown[i].x - ref[i].x);
        total += s.area[i] * ref[i].x;
    }
    EXPECT_GT(err_raw / total, 0.3);
    EXPECT_LT(err_ambient / total, 0.05);
    EXPECT_LT(err_ambient, err_raw / 10);
    // Converged, the ambient term vanishes.
    ASSERT_EQ(solve(*prog, s, {1e-12, 1000000}).status, SolveStatus::Converged);
    for (size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(prog->display()[i].x, ref[i].x, 1e-9);
}

TEST(Stability, ReflectanceOneIsReported) {
    auto s = furnace_sphere(0.5, 1.0);
    s.rho[3] = glm::dvec3(0.2, 1.0, 0.2);
    EXPECT_NE(stability_problem(s).find("reflectance >= 1"), std::string::npos);
    EXPECT_THROW(require_stable(s), LumenError);
    for (auto& solver : all_solvers()) {
        const auto report = solve(*solver, s);
        EXPECT_EQ(report.status, SolveStatus::Unstable) << solver->name();
        EXPECT_FALSE(report.message.empty());
    }
}

TEST(Stability, ClosedWhiteFurnaceIsBounceLimitedOrSingular) {
    auto s = furnace_sphere(1.0, 1.0);  // ρ = 1 with E > 0: no steady state
    // Bounce-limited use still works and stays finite: k sweeps give (k + 1) E.
    auto jacobi = make_jacobi_solver();
    const auto report = solve(*jacobi, s, {1e-9, 50, true});
    EXPECT_EQ(report.status, SolveStatus::IterationCap);
    for (const auto& b : jacobi->radiosity()) EXPECT_NEAR(b.x, 51.0, 1e-9);
    // LU finds the matrix singular instead of dividing by zero.
    auto lu = make_lu_solver();
    EXPECT_THROW(lu->init(s), LumenError);
}

TEST(Stability, DivergingRunStopsBeforeOverflow) {
    auto s = furnace_sphere(0.5, 1.0);
    for (auto& r : s.rho) r = glm::dvec3(1.5, 0.0, 0.5);  // invalid, run anyway
    for (auto& solver : all_solvers()) {
        if (solver->name() == "LU") continue;
        const auto report = solve(*solver, s, {1e-9, 1'000'000, true});
        EXPECT_EQ(report.status, SolveStatus::Unstable) << solver->name();
        for (const auto& b : solver->display())
            EXPECT_TRUE(std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.z))
                << solver->name();
    }
}

TEST(Stability, IterationCapFiresNearRhoOne) {
    const auto s = furnace_sphere(0.999, 1.0);
    auto jacobi = make_jacobi_solver();
    const auto capped = solve(*jacobi, s, {1e-6, 100});
    EXPECT_EQ(capped.status, SolveStatus::IterationCap);
    EXPECT_EQ(capped.iterations, 100);
    EXPECT_NE(capped.message.find("residual"), std::string::npos);
    // Given enough sweeps it converges (about ln(1e-6)/ln(0.999) ≈ 13800 + a margin).
    const auto done = solve(*jacobi, s, {1e-6, 30000});
    EXPECT_EQ(done.status, SolveStatus::Converged);
    EXPECT_NEAR(jacobi->radiosity()[0].x, 1000.0, 1e-2);
}

TEST(Stability, DegeneratePatchesNeverProduceNan) {
    std::vector<Patch> patches = unit_cube_inside(1);
    patches.push_back(make_patch({{0.2, 0.2, 0}, {0.4, 0.2, 0}, {0.6, 0.2, 0}}));  // sliver
    patches.push_back(patches[0]);                                                 // duplicate
    for (auto& p : patches) p.rho = glm::dvec3(0.8);
    patches[1].emission = glm::dvec3(1);
    // Ray casting sees only the nearest of two coincident patches, so rows still sum to 1
    // (symmetrising would hand the copy half of the transfer back and break that).
    auto s = make_system(patches, ray_cast_matrix(patches, 4000, 9, /*symmetrise=*/false));
    EXPECT_EQ(stability_problem(s), "");
    for (auto& solver : all_solvers()) {
        ASSERT_EQ(solve(*solver, s, {1e-10, 100000}).status, SolveStatus::Converged)
            << solver->name();
        for (const auto& b : solver->display())
            EXPECT_TRUE(std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.z));
    }
    // Invalid data is named rather than iterated on.
    s.F(0, 1) = NAN;
    EXPECT_NE(stability_problem(s).find("outside [0, 1]"), std::string::npos);
}

}  // namespace
}  // namespace lumen::render::radiosity

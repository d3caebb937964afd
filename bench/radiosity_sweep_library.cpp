// Library-level speed/accuracy sweep of the classical radiosity module on POV-Ray's
// radiosity/cornell.pov geometry: mesh size x form-factor method x
// solver, each timed and compared with a fine-mesh reference solution. Prints CSV.
//
// The scene file is parsed unchanged; its triangles become patches through the mesher and
// the light panel box is the emitter (E = its ambient x pigment), as in the classic Cornell
// box (POV-Ray's own radiosity instead lights the box from its light_sources). Everything runs
// on one thread (times are CPU seconds); occlusion queries go through the renderer's BVH over the patches.
//
// Usage: radiosity_sweep_library [--quick] [scene.pov] > sweep.csv   (progress on stderr)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "interp/interpret.hpp"
#include "render/bvh.hpp"
#include "render/radiosity/ff_matrix.hpp"
#include "render/radiosity/mesher.hpp"
#include "render/radiosity/solver.hpp"

namespace rad = lumen::render::radiosity;
using lumen::render::Aabb;
using lumen::render::Bvh;
using lumen::render::SlabRay;

namespace {

// CPU seconds of this (single-threaded) process: steadier than wall time on a shared machine.
double cpu_now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// ---- Scene -> patches -------------------------------------------------------------------

struct Surface {
    glm::dvec3 rho{0}, emission{0};
};

Surface surface_of(const lumen::scene::LayeredTexture& tex) {
    Surface s;
    if (tex.empty() || !tex.back()) return s;
    const auto& t = *tex.back();
    const glm::dvec3 pigment = t.pigment ? t.pigment->colour.rgb() : glm::dvec3(0);
    const double diffuse = t.finish ? t.finish->diffuse : 0.6;
    const glm::dvec3 ambient = t.finish ? t.finish->ambient : glm::dvec3(0.1);
    s.rho = diffuse * pigment;
    if (diffuse == 0) s.emission = ambient * pigment;  // the light panel
    return s;
}

// Fronts face the room for the walls and out of the solid for the blocks: a union whose
// bounding box is a proper, non-flat part of the scene's is taken as a solid (cornell.pov's
// triangles are written without a consistent winding).
void orient(std::vector<rad::Patch>& patches, size_t first, const Aabb& scene_box) {
    Aabb box;
    for (size_t i = first; i < patches.size(); ++i)
        for (const auto& v : patches[i].vertices) box.expand(v);
    const glm::dvec3 ext = box.hi - box.lo, scene_ext = scene_box.hi - scene_box.lo;
    bool thick = true, whole = true;
    for (int a = 0; a < 3; ++a) {
        thick = thick && ext[a] > 0.05 * scene_ext[a];
        whole = whole && ext[a] > 0.9 * scene_ext[a];
    }
    const bool solid = thick && !whole;
    const glm::dvec3 centre = solid ? box.centre() : scene_box.centre();
    for (size_t i = first; i < patches.size(); ++i) {
        const double side = glm::dot(patches[i].normal, centre - patches[i].centroid);
        if ((side > 0) == solid) patches[i] = rad::flipped(patches[i]);
    }
}

struct SceneMesh {
    std::vector<rad::Patch> patches;
    int base_count = 0;  // distinct source faces (Patch::object), for matching elements
};

SceneMesh mesh_scene(const lumen::scene::Scene& scene, double max_edge) {
    // Flatten unions into (leaf, inherited texture).
    struct Leaf { const lumen::scene::Object* object; const lumen::scene::LayeredTexture* tex; int group; };
    std::vector<Leaf> leaves;
    int groups = 0;
    std::function<void(const lumen::scene::Object&, const lumen::scene::LayeredTexture*, int)> walk =
        [&](const lumen::scene::Object& o, const lumen::scene::LayeredTexture* tex, int group) {
            const auto* own = o.texture.empty() ? tex : &o.texture;
            if (const auto* csg = std::get_if<lumen::scene::Csg>(&o.shape)) {
                for (const auto& c : csg->children) walk(*c, own, group);
                return;
            }
            if (rad::meshable(o)) leaves.push_back({&o, own, group});
        };
    for (const auto& o : scene.objects) walk(*o, nullptr, groups++);

    Aabb scene_box;
    std::vector<std::vector<rad::Patch>> per_leaf;
    rad::MeshOptions opt;
    opt.max_edge = max_edge;
    for (const auto& leaf : leaves) {
        // Patch::object = the source face, so elements of the same face can be matched.
        per_leaf.push_back(rad::mesh_object(*leaf.object, opt, {glm::dvec3(0), glm::dvec3(0),
                                                                int(per_leaf.size())}));
        for (const auto& p : per_leaf.back())
            for (const auto& v : p.vertices) scene_box.expand(v);
    }
    SceneMesh mesh;
    for (int g = 0; g < groups; ++g) {
        const size_t first = mesh.patches.size();
        std::vector<rad::Patch> backs;
        for (size_t l = 0; l < leaves.size(); ++l) {
            if (leaves[l].group != g) continue;
            const Surface s = leaves[l].tex ? surface_of(*leaves[l].tex) : Surface{};
            const bool emitter = s.emission != glm::dvec3(0);
            // An emitter keeps only its downward faces, and a black copy of them just above
            // stands for its back (the library's hemicube rows score back-face hits).
            for (auto p : per_leaf[l]) {
                if (emitter && p.normal.y > -0.5) continue;
                p.rho = s.rho;
                p.emission = s.emission;
                mesh.patches.push_back(p);
                if (!emitter) continue;
                std::vector<glm::dvec3> v(p.vertices.rbegin(), p.vertices.rend());
                for (auto& x : v) x.y += 0.005;
                backs.push_back(rad::make_patch(v, glm::dvec3(0), glm::dvec3(0),
                                                int(leaves.size()) + p.object));
            }
        }
        orient(mesh.patches, first, scene_box);
        mesh.patches.insert(mesh.patches.end(), backs.begin(), backs.end());
    }
    mesh.base_count = int(2 * leaves.size());
    return mesh;
}

// ---- Occlusion through the BVH ----------------------------------------------------------

class PatchIndex {
public:
    explicit PatchIndex(const std::vector<rad::Patch>& patches) : patches_(patches) {
        std::vector<Aabb> boxes;
        for (const auto& p : patches) {
            Aabb b;
            for (const auto& v : p.vertices) b.expand(v);
            boxes.push_back(b);
        }
        bvh_.build(boxes);
    }

    // Nearest patch other than `skip` along o + t d, t in (t_min, t_max); with `front_only`,
    // -1 when that patch is seen from behind (its back radiates nothing, and ray-cast rows
    // that scored it would break reciprocity, e.g. the floor hidden under the blocks).
    long nearest(const glm::dvec3& o, const glm::dvec3& d, long skip, double t_min,
                 double t_max, bool front_only = false) const {
        long hit = -1;
        double tmax = t_max;
        const auto& order = bvh_.order();
        bvh_.traverse(SlabRay(o, d), t_min, tmax, [&](uint32_t pos) {
            const long j = order[pos];
            if (j == skip) return;
            const double t = rad::intersect(patches_[j], o, d, t_min);
            if (t > 0 && t < tmax) tmax = t, hit = j;
        });
        if (front_only && hit >= 0 && glm::dot(patches_[hit].normal, d) > 0) return -1;
        return hit;
    }

private:
    const std::vector<rad::Patch>& patches_;
    Bvh bvh_;
};

// ---- Form factors and solutions ---------------------------------------------------------

struct Method {
    std::string ff;      // raycast | hemicube | lambert
    int param = 0;       // rays, resolution or visibility samples
    std::string solver;  // lu | jacobi | gauss_seidel | progressive | jacobi3
    double tolerance = 1e-6;  // iterative solvers: residual relative to the brightest emission
};

rad::FormFactorMatrix form_factors(const std::vector<rad::Patch>& patches, const Method& m) {
    if (m.ff == "hemicube") return rad::hemicube_matrix(patches, m.param);
    const PatchIndex index(patches);
    if (m.ff == "lambert") {
        const rad::Visibility visible = [&](const glm::dvec3& a, const glm::dvec3& b) {
            return index.nearest(a, b - a, -1, 1e-6, 1 - 1e-6) < 0;
        };
        return rad::lambert_visibility_matrix(patches, visible, m.param, 1);
    }
    rad::FormFactorMatrix F(patches.size());
    for (size_t i = 0; i < patches.size(); ++i) {
        const rad::NearestPatch nearest = [&](const glm::dvec3& o, const glm::dvec3& d) {
            return index.nearest(o, d, long(i), 1e-9, INFINITY, true);
        };
        const auto row = rad::ray_cast_row(patches, i, m.param, 7919 * i + 1, nearest);
        std::copy(row.begin(), row.end(), F.f.begin() + i * F.n);
    }
    rad::symmetrise(F, patches);
    return F;
}

// Averaging noisy ray-cast pairs, or the hemicube's discretised delta form factors, can lift
// a nearly closed row (a block face by the floor) just past 1, which the solvers reject as
// unstable: such rows are scaled back to 1.
rad::FormFactorMatrix bounded_form_factors(const std::vector<rad::Patch>& patches,
                                           const Method& m) {
    auto F = form_factors(patches, m);
    for (size_t i = 0; i < F.n; ++i)
        if (const double sum = F.row_sum(i); sum > 1)
            for (size_t j = 0; j < F.n; ++j) F(i, j) /= sum;
    return F;
}

std::unique_ptr<rad::Solver> make_solver(const std::string& name) {
    if (name == "lu") return rad::make_lu_solver();
    if (name == "gauss_seidel") return rad::make_gauss_seidel_solver();
    if (name == "progressive") return rad::make_progressive_solver();
    return rad::make_jacobi_solver();
}

struct Run {
    std::vector<glm::dvec3> B;
    double ff_s = 0, solve_s = 0;
    int iterations = 0;
};

// Iterative solvers stop at the method's residual; jacobi3 is POV's recursion_limit 3 (three
// bounces).
Run run(const std::vector<rad::Patch>& patches, const Method& m) {
    Run r;
    double t0 = cpu_now();
    auto F = bounded_form_factors(patches, m);
    r.ff_s = cpu_now() - t0;
    const auto s = rad::make_system(patches, std::move(F));
    double e_max = 0;
    for (const auto& e : s.emission) e_max = std::max({e_max, e.x, e.y, e.z});
    auto solver = make_solver(m.solver);
    t0 = cpu_now();
    rad::SolveOptions opt;
    opt.tolerance = m.tolerance * e_max;
    if (m.solver == "jacobi3") {
        solver->init(s);
        for (int k = 0; k < 3; ++k) solver->step();
        r.iterations = 3;
    } else {
        const auto report = rad::solve(*solver, s, opt);
        r.iterations = report.iterations;
        if (report.status != rad::SolveStatus::Converged)
            throw std::runtime_error(m.ff + " " + m.solver + ": " + report.message);
    }
    r.solve_s = cpu_now() - t0;
    r.B = solver->display();
    return r;
}

// ---- Error against the reference --------------------------------------------------------

bool inside(const rad::Patch& p, const glm::dvec3& x) {
    const size_t n = p.vertices.size();
    for (size_t i = 0; i < n; ++i) {
        const auto& a = p.vertices[i];
        const auto& b = p.vertices[(i + 1) % n];
        if (glm::dot(glm::cross(b - a, x - a), p.normal) < -1e-9) return false;
    }
    return true;
}

// Area-weighted relative L1 error of the element radiosities over all channels against the
// reference's area mean over each element. Reference elements are assigned by their centroid
// to the element of the same source face that holds it; averaging over them keeps the
// reference's own Monte Carlo noise small.
double relative_l1(const SceneMesh& coarse, const std::vector<glm::dvec3>& B,
                   const SceneMesh& ref, const std::vector<glm::dvec3>& B_ref) {
    std::vector<std::vector<size_t>> by_base(coarse.base_count);
    for (size_t i = 0; i < coarse.patches.size(); ++i) by_base[coarse.patches[i].object].push_back(i);
    std::vector<double> area(B.size(), 0.0);
    std::vector<glm::dvec3> flux(B.size(), glm::dvec3(0));
    for (size_t r = 0; r < ref.patches.size(); ++r) {
        const auto& e = ref.patches[r];
        const auto& candidates = by_base.at(e.object);
        size_t match = candidates.front();
        double best = INFINITY;
        for (size_t i : candidates) {
            if (inside(coarse.patches[i], e.centroid)) { match = i; break; }
            const double d = glm::length(coarse.patches[i].centroid - e.centroid);
            if (d < best) best = d, match = i;
        }
        area[match] += e.area;
        flux[match] += e.area * B_ref[r];
    }
    double num = 0, den = 0;
    for (size_t i = 0; i < B.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            num += std::abs(area[i] * B[i][c] - flux[i][c]);
            den += flux[i][c];
        }
    return den > 0 ? num / den : 0;
}

}  // namespace

int sweep(int argc, char** argv) {
    bool quick = false;
    double ref_edge = 0;
    std::string path = "/usr/share/povray-3.7/scenes/radiosity/cornell.pov";
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--ref-edge") && i + 1 < argc) ref_edge = std::atof(argv[++i]);
        else path = argv[i];
    }
    lumen::SourceManager sources;
    const auto scene = lumen::interp::interpret_file(sources, path, {});
    if (!(ref_edge > 0)) ref_edge = quick ? 8 : 4;

    // Reference: the finest mesh, many rays per element, Gauss-Seidel to round-off (LU would
    // take minutes at this size).
    const SceneMesh ref = mesh_scene(scene, ref_edge);
    const Method ref_method{"raycast", quick ? 4096 : 16384, "gauss_seidel", 1e-10};
    std::fprintf(stderr, "reference: edge %g, %zu elements...\n", ref_edge, ref.patches.size());
    const Run ref_run = run(ref.patches, ref_method);
    std::fprintf(stderr, "reference: form factors %.1f s, solve %.1f s\n", ref_run.ff_s,
                 ref_run.solve_s);

    // Its own noise: the same mesh with a quarter of the rays has about twice the reference's
    // Monte Carlo error per element (the error below averages it over coarser elements).
    {
        const Run check = run(ref.patches, {"raycast", ref_method.param / 4, "gauss_seidel", 1e-10});
        std::printf("# reference: max_edge %g, %zu elements, raycast %d rays, gauss_seidel to 1e-10; "
                    "form factors %.1f s; with a quarter of the rays: rel_l1 %.4g\n",
                    ref_edge, ref.patches.size(), ref_method.param, ref_run.ff_s,
                    relative_l1(ref, check.B, ref, ref_run.B));
    }
    std::printf("n,max_edge,method,form_factors,ff_param,solver,ff_cpu_s,solve_cpu_s,total_cpu_s,iterations,"
                "rel_l1\n");
    auto report = [&](const SceneMesh& mesh, double edge, const Method& m) {
        const Run r = run(mesh.patches, m);
        const double err = relative_l1(mesh, r.B, ref, ref_run.B);
        std::printf("%zu,%g,%s %d %s,%s,%d,%s,%.4f,%.4f,%.4f,%d,%.6g\n", mesh.patches.size(),
                    edge, m.ff.c_str(), m.param, m.solver.c_str(), m.ff.c_str(), m.param,
                    m.solver.c_str(), r.ff_s, r.solve_s, r.ff_s + r.solve_s, r.iterations, err);
        std::fflush(stdout);
    };

    const std::vector<double> edges = quick ? std::vector<double>{24, 16} : std::vector<double>{24, 16, 12, 8};
    for (double edge : edges) {
        const SceneMesh mesh = mesh_scene(scene, edge);
        const double n = double(mesh.patches.size());
        std::fprintf(stderr, "edge %g: %zu elements\n", edge, mesh.patches.size());
        for (int rays : quick ? std::vector<int>{64, 256} : std::vector<int>{16, 64, 256, 1024, 4096})
            report(mesh, edge, {"raycast", rays, "lu"});
        for (int res : quick ? std::vector<int>{16} : std::vector<int>{16, 32, 64})
            if (n * n * 3 * res * res < 1.5e9)  // brute-force hemicube: keep each run short
                report(mesh, edge, {"hemicube", res, "lu"});
        if (n < 400) report(mesh, edge, {"lambert", 16, "lu"});  // n^2 quadratures
        for (const char* solver : {"jacobi", "gauss_seidel", "progressive", "jacobi3"})
            report(mesh, edge, {"raycast", 256, solver});
    }
    return 0;
}

int main(int argc, char** argv) {
    try {
        return sweep(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "radiosity_sweep_library: %s\n", e.what());
        return 1;
    }
}

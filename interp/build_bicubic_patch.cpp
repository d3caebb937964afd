// bicubic_patch { type T [flatness F] [u_steps N] [v_steps M] [uv_vectors ...] [accuracy A]
// P0, ..., P15 modifiers }: POV-Ray 3.7 renders a patch as the triangles of its subdivision
// (type 1 builds them once, type 0 per ray, with the same result), each triangle shaded with
// the patch's exact normals at its corners. So the patch becomes a smooth mesh here: the
// subdivision is POV's (halving by de Casteljau until the sub-net is flatter than `flatness`
// or the steps are used up), and a hit on it is the hit on those triangles.
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

// A patch net: CP[i][j] = P(4i + j), i along u (the outer index), j along v.
using Net = std::array<std::array<glm::dvec3, 4>, 4>;

constexpr int kMaxSteps = 10;  // 4^10 leaves; POV-Ray has no bound (steps 12 took it 3.7 GB)

// The cubic Bernstein weights at t.
std::array<double, 4> cubic_weights(double t) {
    const double s = 1 - t;
    return {s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t};
}

// The derivative at t of the cubic Bezier curve through p[0..3].
glm::dvec3 cubic_tangent(const std::array<glm::dvec3, 4>& p, double t) {
    const double s = 1 - t;
    return 3.0 * (s * s * (p[1] - p[0]) + 2 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
}

// The patch's exact normal at (u, v): S_u × S_v, (1, 0, 0) where it vanishes (POV-Ray's rule).
glm::dvec3 patch_normal(const Net& cp, double u, double v) {
    const std::array<double, 4> wu = cubic_weights(u), wv = cubic_weights(v);
    glm::dvec3 su(0), sv(0);
    for (int k = 0; k < 4; ++k) {
        const std::array<glm::dvec3, 4> column = {cp[0][k], cp[1][k], cp[2][k], cp[3][k]};
        su += wv[k] * cubic_tangent(column, u);  // d/du of column k, weighted in v
        sv += wu[k] * cubic_tangent(cp[k], v);   // d/dv of row k, weighted in u
    }
    const glm::dvec3 n = glm::cross(su, sv);
    const double nn = glm::dot(n, n);
    if (nn <= 1e-10 * glm::dot(su, su) * glm::dot(sv, sv) || !(nn > 0)) return {1, 0, 0};
    return n / std::sqrt(nn);
}

// de Casteljau at 1/2 of the four points a..d: the low half into lo, the high into hi.
void halve(const glm::dvec3 (&p)[4], glm::dvec3 (&lo)[4], glm::dvec3 (&hi)[4]) {
    const glm::dvec3 ab = (p[0] + p[1]) / 2.0, bc = (p[1] + p[2]) / 2.0, cd = (p[2] + p[3]) / 2.0;
    const glm::dvec3 abc = (ab + bc) / 2.0, bcd = (bc + cd) / 2.0, m = (abc + bcd) / 2.0;
    lo[0] = p[0], lo[1] = ab, lo[2] = abc, lo[3] = m;
    hi[0] = m, hi[1] = bcd, hi[2] = cd, hi[3] = p[3];
}

// The net split at u = 1/2 (first index) or v = 1/2 (second).
void split(const Net& net, bool in_u, Net& lo, Net& hi) {
    for (int k = 0; k < 4; ++k) {
        glm::dvec3 p[4], a[4], b[4];
        for (int m = 0; m < 4; ++m) p[m] = in_u ? net[m][k] : net[k][m];
        halve(p, a, b);
        for (int m = 0; m < 4; ++m) {
            (in_u ? lo[m][k] : lo[k][m]) = a[m];
            (in_u ? hi[m][k] : hi[k][m]) = b[m];
        }
    }
}

// How far the net's points stray from the plane of three of its corners; -1 where the
// corners span no plane. Measured in world space: POV-Ray subdivides the transformed patch.
double flatness_of(const Net& local, const scene::Transform& to_world) {
    constexpr double eps = 1e-10;
    Net net;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) net[i][j] = to_world.point(local[i][j]);
    glm::dvec3 a = net[0][0], b = net[0][3], c = net[3][0];
    if (glm::length(b - a) < eps) b = net[3][3];
    else if (glm::length(c - a) < eps) c = net[3][3];
    glm::dvec3 n = glm::cross(b - a, c - a);
    const double l = glm::length(n);
    if (!(l > eps)) return -1;
    n /= l;
    double worst = 0;
    for (const auto& row : net)
        for (const glm::dvec3& p : row) worst = std::max(worst, std::fabs(glm::dot(p - a, n)));
    return worst;
}

struct Tessellation {
    const Net& patch;
    double flatness;
    int u_steps, v_steps;
    const scene::Transform& to_world;
    scene::Mesh& mesh;

    // A leaf's four corners, each with the patch's exact normal, and its two triangles
    // (C00, C03, C33) and (C00, C33, C30); a degenerate triangle is dropped, as POV drops it.
    void leaf(const Net& net, double u0, double u1, double v0, double v1) {
        const int base = int(mesh.vertices.size());
        const glm::dvec3 c[4] = {net[0][0], net[0][3], net[3][3], net[3][0]};
        const glm::dvec2 uv[4] = {{u0, v0}, {u0, v1}, {u1, v1}, {u1, v0}};
        for (int k = 0; k < 4; ++k) {
            mesh.vertices.push_back(c[k]);
            mesh.normals.push_back(patch_normal(patch, uv[k].x, uv[k].y));
            mesh.uvs.push_back(uv[k]);
        }
        for (const std::array<int, 3>& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
            const glm::dvec3 b0 = c[t[1]] - c[t[0]], b1 = c[t[2]] - c[t[0]], n = glm::cross(b0, b1);
            if (glm::dot(n, n) <= 1e-10 * glm::dot(b0, b0) * glm::dot(b1, b1)) continue;
            scene::Mesh::Face f;
            for (int k = 0; k < 3; ++k) f.v[k] = f.n[k] = f.uv[k] = base + t[k];
            mesh.faces.push_back(f);
        }
    }
    void node(const Net& net, double u0, double u1, double v0, double v1, int depth) {
        const double flat = flatness_of(net, to_world);
        if ((flat >= 0 && flat < flatness) || (depth >= u_steps && depth >= v_steps))
            return leaf(net, u0, u1, v0, v1);
        const double um = (u0 + u1) / 2, vm = (v0 + v1) / 2;
        Net lo, hi;
        if (depth >= u_steps) {
            split(net, false, lo, hi);
            node(lo, u0, u1, v0, vm, depth + 1);
            node(hi, u0, u1, vm, v1, depth + 1);
            return;
        }
        split(net, true, lo, hi);
        if (depth >= v_steps) {
            node(lo, u0, um, v0, v1, depth + 1);
            node(hi, um, u1, v0, v1, depth + 1);
            return;
        }
        Net a, b;
        split(lo, false, a, b);
        node(a, u0, um, v0, vm, depth + 1);
        node(b, u0, um, vm, v1, depth + 1);
        split(hi, false, a, b);
        node(a, um, u1, v0, vm, depth + 1);
        node(b, um, u1, vm, v1, depth + 1);
    }
};

}  // namespace

scene::ObjectPtr build_bicubic_patch(ItemCursor& cur) {
    std::optional<int> type;
    double flatness = 0;
    int steps[2] = {0, 0};
    // Texture corners s0..s3 at P0, P3, P15, P12 (POV-Ray's defaults).
    std::vector<glm::dvec2> corners = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    auto read_steps = [&](int k, const char* word) {
        const SourceLoc loc = cur.here();
        const double n = cur.expect_float(word);
        if (!(n >= 0 && n <= kMaxSteps))
            cur.fail(loc, std::string(word) + " must be 0 to " + std::to_string(kMaxSteps) +
                              " in lumen (each step doubles the triangles)");
        steps[k] = int(n);
    };
    auto read_type = [&](SourceLoc loc, double t) {
        if (!(t >= 0 && t < 4)) cur.fail(loc, "bicubic_patch type must be 0 or 1");
        type = int(t);
        if (*type >= 2) cur.warn(loc, "bicubic_patch type 2 and 3 are rendered as type 1");
    };
    if (cur.next_is_float()) {
        // The old form: `T [F] US VS`, with the flatness only for types 2 and 3.
        const SourceLoc loc = cur.here();
        read_type(loc, cur.expect_float(""));
        flatness = *type >= 2 ? cur.expect_float("") : 0.1;
        read_steps(0, "u_steps");
        read_steps(1, "v_steps");
    }
    for (;;) {
        const SourceLoc loc = cur.here();
        if (cur.accept_keyword("type")) read_type(loc, cur.expect_float("type"));
        else if (cur.accept_keyword("flatness")) flatness = cur.expect_float("flatness");
        else if (cur.accept_keyword("u_steps")) read_steps(0, "u_steps");
        else if (cur.accept_keyword("v_steps")) read_steps(1, "v_steps");
        else if (cur.accept_keyword("accuracy")) cur.expect_float("accuracy");  // unused by POV
        else if (cur.accept_keyword("uv_vectors")) {
            for (glm::dvec2& s : corners) s = read_vector2(cur, "uv_vectors");
        } else break;
    }
    if (!type) cur.fail(cur.block_loc(), "bicubic_patch needs its type (type 0 or type 1)");
    Net net;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) net[i][j] = cur.expect_vector("bicubic_patch");

    scene::Object obj;
    obj.loc = cur.block_loc();
    scene::Mesh& mesh = obj.shape.emplace<scene::Mesh>();
    mesh.patch_corners = corners;
    read_object_modifiers(cur, obj, [](const Item&) { return false; }, {});
    Tessellation{net, flatness, steps[0], steps[1], obj.transform, mesh}.node(net, 0, 1, 0, 1, 0);
    return std::make_shared<scene::Object>(std::move(obj));
}

}  // namespace lumen::interp

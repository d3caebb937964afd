#include "render/camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "render/normal.hpp"
#include "scene/object.hpp"

namespace lumen::render {
namespace {

constexpr double kPi = std::numbers::pi;

// v turned by t radians about the unit axis k (Rodrigues).
glm::dvec3 rotated(const glm::dvec3& v, const glm::dvec3& k, double t) {
    return v * std::cos(t) + glm::cross(k, v) * std::sin(t) + k * glm::dot(k, v) * (1 - std::cos(t));
}

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
    const double l = glm::length(v);
    return l > 0 ? v / l : glm::dvec3(0);
}

}  // namespace

CameraModel::CameraModel(const scene::Camera& camera, int width, int height)
    : camera_(camera),
      right_unit_(unit_or_zero(camera.right)),
      up_unit_(unit_or_zero(camera.up)),
      direction_unit_(unit_or_zero(camera.direction)),
      right_length_(glm::length(camera.right)),
      up_length_(glm::length(camera.up)),
      width_(width),
      height_(height) {
    if (!camera.mesh) return;
    // mesh_camera: each face's centroid and unit normal (P3 - P1) x (P2 - P1), POV-Ray's
    // winding; distribution 1 numbers the faces of all meshes one after another.
    const scene::Camera::MeshRays& m = *camera.mesh;
    rays_per_sample_ = m.rays;
    auto add_faces = [](const scene::Mesh& mesh, std::vector<Face>& out) {
        for (const scene::Mesh::Face& f : mesh.faces) {
            const glm::dvec3 &a = mesh.vertices[f.v[0]], &b = mesh.vertices[f.v[1]],
                             &c = mesh.vertices[f.v[2]];
            out.push_back({(a + b + c) / 3.0, unit_or_zero(glm::cross(c - a, b - a))});
        }
    };
    // Copies of one mesh (the usual way to write many) share their vertices and faces, and
    // so one face table here: a hundred copies of a 640x480 mesh would otherwise take 1.5 GB.
    std::map<std::pair<const void*, const void*>, std::shared_ptr<const std::vector<Face>>> shared;
    std::vector<Face> joined;  // distribution 1
    for (const auto& obj : m.meshes) {
        const auto* mesh = obj ? std::get_if<scene::Mesh>(&obj->shape) : nullptr;
        if (!mesh) continue;
        if (m.distribution == 1) {
            if (meshes_.empty()) meshes_.push_back({nullptr, obj->transform});
            add_faces(*mesh, joined);
            continue;
        }
        auto& faces = shared[{mesh->vertices.identity(), mesh->faces.identity()}];
        if (!faces) {
            auto table = std::make_shared<std::vector<Face>>();
            add_faces(*mesh, *table);
            faces = std::move(table);
        }
        meshes_.push_back({faces, obj->transform});
        if (m.distribution == 3) {  // POV-Ray uses only the first mesh
            index_uv_cells(*mesh);
            break;
        }
    }
    if (!meshes_.empty() && m.distribution == 1)
        meshes_.front().faces = std::make_shared<const std::vector<Face>>(std::move(joined));
}

size_t CameraModel::face_tables() const {
    std::vector<const void*> tables;
    for (const MeshFaces& m : meshes_)
        if (std::find(tables.begin(), tables.end(), m.faces.get()) == tables.end()) tables.push_back(m.faces.get());
    return tables.size();
}

namespace {

// POV-Ray's uv buckets: tenths, truncated towards zero, the last one open upwards. Its faces
// below u = -0.1 would fall outside the table; no sample lies there.
int pov_bucket(double t) { return std::clamp(int(std::clamp(t * 10, -1e9, 1e9)), 0, 9); }

glm::dvec2 corner_uv(const scene::Mesh& mesh, int i) {
    return i >= 0 && size_t(i) < mesh.uvs.size() ? mesh.uvs[size_t(i)] : glm::dvec2(0);
}

// Twice the uv triangle's signed area.
double uv_scale(const std::array<glm::dvec2, 3>& p) {
    return (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
}

// The uv's barycentric weights in the face's uv triangle, with POV-Ray's formulas (so that
// samples on shared edges go to the same face), or false for a degenerate uv triangle (POV
// would start a ray at a NaN origin).
bool uv_weights(const std::array<glm::dvec2, 3>& p, double u, double v, glm::dvec3& b) {
    const double scale = uv_scale(p);
    if (!(scale != 0) || !std::isfinite(scale)) return false;
    b[0] = ((p[1].x - u) * (p[2].y - v) - (p[2].x - u) * (p[1].y - v)) / scale;
    b[1] = ((p[2].x - u) * (p[0].y - v) - (p[0].x - u) * (p[2].y - v)) / scale;
    b[2] = ((p[0].x - u) * (p[1].y - v) - (p[1].x - u) * (p[0].y - v)) / scale;
    return true;
}

}  // namespace

void CameraModel::index_uv_cells(const scene::Mesh& mesh) {
    uv_mesh_ = &mesh;
    const size_t n = mesh.faces.size();
    // POV-Ray's 10 x 10 buckets, each split k x k so that a cell holds a few faces of a mesh
    // spread evenly over the unit square. A face is listed where its POV bucket range allows
    // and its uv bounds (widened a little, for rounding on the edges) reach, so every face
    // POV-Ray would find at a sample is a candidate there and no other.
    const int k = std::clamp(int(std::ceil(std::sqrt(double(n) / 100))), 1, 64);
    cells_ = 10 * k;
    struct Span { int u0, u1, v0, v1; };
    std::vector<Span> spans(n, Span{0, -1, 0, -1});
    std::vector<uint32_t> count(size_t(cells_) * cells_ + 1, 0);
    auto range = [&](double lo, double hi, int& a, int& b) {
        const double g = cells_;
        a = std::max(int(std::clamp(std::floor(lo * g - 0.01), 0.0, g)), pov_bucket(lo) * k);
        b = std::min(int(std::clamp(std::floor(hi * g + 0.01), 0.0, g - 1)), pov_bucket(hi) * k + k - 1);
    };
    for (size_t i = 0; i < n; ++i) {
        const scene::Mesh::Face& f = mesh.faces[i];
        if ((*meshes_.front().faces)[i].normal == glm::dvec3(0)) continue;  // POV-Ray drops these
        const std::array<glm::dvec2, 3> p{corner_uv(mesh, f.uv[0]), corner_uv(mesh, f.uv[1]),
                                          corner_uv(mesh, f.uv[2])};
        const double scale = uv_scale(p);
        if (!(scale != 0) || !std::isfinite(scale)) continue;
        const glm::dvec2 lo = glm::min(p[0], glm::min(p[1], p[2]));
        const glm::dvec2 hi = glm::max(p[0], glm::max(p[1], p[2]));
        Span& s = spans[i];
        range(lo.x, hi.x, s.u0, s.u1);
        range(lo.y, hi.y, s.v0, s.v1);
        for (int cv = s.v0; cv <= s.v1; ++cv)
            for (int cu = s.u0; cu <= s.u1; ++cu) ++count[size_t(cv) * cells_ + cu + 1];
    }
    for (size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    cell_start_ = count;
    cell_faces_.resize(count.back());
    for (size_t i = 0; i < n; ++i) {  // in mesh order, so each cell's list is too
        const Span& s = spans[i];
        for (int cv = s.v0; cv <= s.v1; ++cv)
            for (int cu = s.u0; cu <= s.u1; ++cu) cell_faces_[count[size_t(cv) * cells_ + cu]++] = uint32_t(i);
    }
}

bool CameraModel::uv_ray(double u, double v, glm::dvec3& origin, glm::dvec3& dir) const {
    if (!uv_mesh_ || !std::isfinite(u) || !std::isfinite(v)) return false;
    const scene::Mesh& mesh = *uv_mesh_;
    // The sample's cell, kept inside the POV bucket it falls in.
    const int k = cells_ / 10;
    auto cell = [&](double t) {
        const int c = pov_bucket(t);
        return std::clamp(int(std::clamp(std::floor(t * cells_), 0.0, double(cells_))), c * k,
                          c * k + k - 1);
    };
    const size_t c = size_t(cell(v)) * cells_ + cell(u);
    for (uint32_t j = cell_start_[c]; j < cell_start_[c + 1]; ++j) {
        const scene::Mesh::Face& f = mesh.faces[cell_faces_[j]];
        glm::dvec3 b;
        if (!uv_weights({corner_uv(mesh, f.uv[0]), corner_uv(mesh, f.uv[1]), corner_uv(mesh, f.uv[2])}, u,
                        v, b) ||
            b[0] < 0 || b[1] < 0 || b[2] < 0)
            continue;
        origin = mesh.vertices[f.v[0]] * b[0] + mesh.vertices[f.v[1]] * b[1] + mesh.vertices[f.v[2]] * b[2];
        dir = (*meshes_.front().faces)[cell_faces_[j]].normal;
        const bool has_normals = std::all_of(f.n.begin(), f.n.end(), [&](int i) {
            return i >= 0 && size_t(i) < mesh.normals.size();
        });
        if (camera_.mesh->smooth && has_normals) {
            // POV-Ray blends the unit vertex normals and leaves the blend unnormalised (it
            // scales the location.z offset).
            glm::dvec3 blend(0);
            for (int i = 0; i < 3; ++i) blend += b[i] * unit_or_zero(mesh.normals[size_t(f.n[i])]);
            if (glm::dot(blend, blend) > 0) dir = blend;
        }
        return true;
    }
    return false;
}

bool CameraModel::mesh_ray(double x, double y, int k, Ray& ray) const {
    const scene::Camera::MeshRays& m = *camera_.mesh;
    // POV-Ray's sample coordinates: column x + 0.5, row y - 0.5, clamped to the image (so
    // rows 0 and 1 both use the first row of faces).
    const int w = int(width_);
    const double cx = std::clamp(x + 0.5, 0.0, width_ - 1), cy = std::clamp(y - 0.5, 0.0, height_ - 1);
    size_t mesh = 0;
    long long face = 0;
    glm::dvec3 origin, dir;
    switch (m.distribution) {
        case 0:  // ray k on mesh k, one face per pixel
            mesh = size_t(k);
            face = (long long)(cy) * w + (long long)(cx);
            break;
        case 1: {  // the meshes joined; rays after the first fall past the faces (as in POV)
            face = (long long)(cy) * w + (long long)(cx) + (long long)(k) * (long long)(
                       meshes_.empty() ? 0 : meshes_[0].faces->size());
            break;
        }
        case 2: {  // the meshes side by side, each W / n columns wide
            const int columns = std::max(1, w / int(std::max<size_t>(1, meshes_.size())));
            mesh = size_t(cx / (width_ / double(meshes_.size())));
            face = (long long)(cy) * columns + (long long)(cx);
            break;
        }
        default:  // 3: the pixel's place in the uv map, v upwards
            if (meshes_.empty() || !uv_ray((cx - 0.5) / width_, 1 - (cy + 0.5) / height_, origin, dir))
                return false;
            break;
    }
    if (m.distribution != 3) {
        if (mesh >= meshes_.size() || face < 0 || size_t(face) >= meshes_[mesh].faces->size())
            return false;
        const Face& f = (*meshes_[mesh].faces)[size_t(face)];
        origin = f.centre;
        dir = f.normal;
    }
    origin += m.offset * dir;
    if (m.reverse) dir = -dir;
    // POV-Ray moves the direction as a normal (the inverse transpose).
    const scene::Transform& xf = meshes_[mesh].to_world;
    ray.origin = xf.point(origin);
    ray.dir = xf.normal(dir);
    return true;
}

bool CameraModel::project(double x, double y, Ray& ray, glm::dvec3& np) const {
    using scene::CameraType;
    const scene::Camera& c = camera_;
    // POV samples at the pixel centre and flips y so the top row looks up: fx runs 0..1 left
    // to right, fy 0..1 bottom to top.
    const double fx = (x + 0.5) / width_;
    const double fy = (height_ - 0.5 - y) / height_;
    const glm::dvec3 &R = right_unit_, &U = up_unit_, &D = direction_unit_;
    ray.origin = c.location;
    switch (c.type) {
        case CameraType::MeshCamera:
            if (c.mesh) return false;  // mesh_ray() (a camera copied without its meshes: below)
            [[fallthrough]];
        case CameraType::Perspective:
        case CameraType::Orthographic: {
            const double x0 = fx - 0.5, y0 = fy - 0.5;
            np = {x0, y0, 0};
            if (c.type == CameraType::Orthographic) {
                ray.origin += x0 * c.right + y0 * c.up;
                ray.dir = c.direction;
            } else {
                ray.dir = c.direction + x0 * c.right + y0 * c.up;
            }
            return true;
        }
        case CameraType::Fisheye:
        case CameraType::Omnimax: {
            double x0 = 2 * fx - 1, y0 = 2 * fy - 1;
            if (c.type == CameraType::Fisheye) {
                x0 *= right_length_, y0 *= up_length_;
            } else {
                // The dome's aspect: POV stretches wide images in x and narrow ones in y.
                const double a = right_length_ / up_length_, k = 1.283458;
                if (a > k) x0 *= a / k, y0 = (y0 - 1) / k + 1;
                else if (a > 1) y0 = (y0 - 1) / a + 1;
                else y0 /= a;
            }
            const double r = std::sqrt(x0 * x0 + y0 * y0);
            if (r > 1) return false;
            const double phi = r == 0 ? 0 : x0 < 0 ? kPi - std::asin(y0 / r) : std::asin(y0 / r);
            const double theta = c.type == CameraType::Fisheye
                                     ? r * c.angle * kPi / 360
                                     : 1.411269 * r - 0.09439 * r * r * r + 0.25674 * std::pow(r, 5);
            // Omnimax: nothing below 45 degrees under the horizon (tan 135° = -1).
            if (c.type == CameraType::Omnimax && std::sin(phi) * std::sin(theta) < -std::cos(theta))
                return false;
            np = {phi, theta, 0};
            ray.dir = std::cos(phi) * std::sin(theta) * R + std::sin(phi) * std::sin(theta) * U +
                      std::cos(theta) * D;
            return true;
        }
        case CameraType::UltraWideAngle: {
            const double x0 = (fx - 0.5) * c.angle * kPi / 180;
            const double y0 = (fy - 0.5) * c.angle * (up_length_ / right_length_) * kPi / 180;
            np = {x0, y0, 0};
            ray.dir = std::sin(x0) * R + std::sin(y0) * U + std::cos(x0) * std::cos(y0) * D;
            return true;
        }
        case CameraType::Panoramic: {
            const double a = (1 - fx) * kPi, b = (2 * fy - 1) * kPi / 2;
            const double t = std::fabs(kPi / 2 - std::fabs(b)) < 1e-10 ? (b > 0 ? 1e10 : -1e10)
                                                                        : std::tan(b);
            np = {a, b, 0};
            ray.dir = std::cos(a) * c.right + t * c.up + std::sin(a) * c.direction;
            return true;
        }
        case CameraType::Spherical: {
            const double a = (fx - 0.5) * c.angle * kPi / 180;
            const double b = (fy - 0.5) * c.vertical_angle * kPi / 180;
            np = {a, b, 0};
            ray.dir = rotated(rotated(D, R, -b), U, a);
            return true;
        }
        case CameraType::Cylinder: {
            const double u = fx - 0.5, v = fy - 0.5, theta = c.angle * kPi / 180;
            // Types 1 and 3 span |up| along the axis, 2 and 4 |right|.
            const double s = c.cylinder_type == 1 || c.cylinder_type == 3 ? up_length_ : right_length_;
            // The normal sees the angle along the curved direction, the length along the axis.
            const bool vertical = c.cylinder_type == 1 || c.cylinder_type == 3;
            np = vertical ? glm::dvec3(u * theta, v * s, 0) : glm::dvec3(u * s, v * theta, 0);
            switch (c.cylinder_type) {
                case 1: ray.dir = std::sin(u * theta) * R + v * s * U + std::cos(u * theta) * D; break;
                case 2: ray.dir = u * s * R + std::sin(v * theta) * U + std::cos(v * theta) * D; break;
                case 3:
                    ray.origin += v * s * U;
                    ray.dir = std::sin(u * theta) * R + std::cos(u * theta) * D;
                    break;
                default:
                    ray.origin += u * s * R;
                    ray.dir = std::sin(v * theta) * U + std::cos(v * theta) * D;
                    break;
            }
            return true;
        }
    }
    return false;
}

std::optional<Ray> CameraModel::ray(double x, double y, int k) const {
    Ray r;
    glm::dvec3 np;
    if (camera_.mesh ? !mesh_ray(x, y, k, r) : !project(x, y, r, np)) return std::nullopt;
    const double l = glm::length(r.dir);
    if (!(l > 0) || !std::isfinite(l)) return std::nullopt;
    r.dir /= l;
    if (camera_.normal && !camera_.mesh) r.dir = perturbed_normal(*camera_.normal, r.dir, np);
    return r;
}

}  // namespace lumen::render

// Pixel -> primary ray (POV-Ray 3.7's rules). The scene camera arrives fixed up by the
// interpreter (angle, look_at, orthographic scaling, transforms), so this is only the mapping.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "render/ray.hpp"
#include "scene/camera.hpp"
#include "scene/transform.hpp"

namespace lumen::scene {
struct Mesh;  // scene/shapes.hpp
}

namespace lumen::render {

class CameraModel {
public:
    // width/height are always the full image size, even for partial renders.
    CameraModel(const scene::Camera& camera, int width, int height);

    // Ray through image position (x, y): x from the left, y from the top, in pixel units;
    // (x, y) is the pixel's centre before the half-pixel offset is added, so pixel (i, j)
    // is sampled at ray(i, j) and anti-aliasing passes fractional positions. None where the
    // projection has no ray (outside a fisheye's or omnimax's circle): POV shows that sample
    // as black, fully transparent, not as the background.
    std::optional<Ray> ray(double x, double y) const { return ray(x, y, 0); }
    // A mesh camera shoots several rays per sample (their colours are averaged over those
    // shot); ray k of the sample at (x, y). Every other camera has one.
    int rays_per_sample() const { return rays_per_sample_; }
    std::optional<Ray> ray(double x, double y, int k) const;
    const scene::Camera& camera() const { return camera_; }
    // mesh_camera: how many face tables its meshes hold (copies of one mesh share one).
    size_t face_tables() const;

private:
    // The unnormalised direction (and, for the projections that move it, the origin) of the
    // sample at (x, y), and the coordinates a camera normal is evaluated at.
    bool project(double x, double y, Ray& ray, glm::dvec3& normal_point) const;
    // mesh_camera: the face a ray starts on, POV-Ray's face numbering per distribution.
    bool mesh_ray(double x, double y, int k, Ray& ray) const;
    // Distribution 3: the point of the first mesh whose uv is (u, v), and its normal (the
    // vertex normals blended with `smooth`, not normalised); false where no face covers it.
    bool uv_ray(double u, double v, glm::dvec3& origin, glm::dvec3& dir) const;
    void index_uv_cells(const scene::Mesh& mesh);

    struct Face {
        glm::dvec3 centre, normal;  // object space; normal unit length
    };
    struct MeshFaces {
        std::shared_ptr<const std::vector<Face>> faces;  // shared by copies of one mesh
        scene::Transform to_world;
    };
    std::vector<MeshFaces> meshes_;  // distribution 1: one list, all meshes' faces in order
    // Distribution 3: the first mesh, and a uv grid of cells_ x cells_ over [0, 1)^2 (the
    // border cells reach out to infinity), each cell listing in mesh order the faces whose uv
    // bounds touch it, so that a cell's first containing face is the mesh's first.
    const scene::Mesh* uv_mesh_ = nullptr;
    int cells_ = 0;
    std::vector<uint32_t> cell_start_, cell_faces_;
    int rays_per_sample_ = 1;

    scene::Camera camera_;
    glm::dvec3 right_unit_, up_unit_, direction_unit_;
    double right_length_, up_length_;
    double width_, height_;
};

}  // namespace lumen::render

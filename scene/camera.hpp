// The camera after POV's fix-ups (angle, look_at, orthographic scaling, transforms), so the
// renderer only maps pixels to rays (POV-Ray 3.7's rules).
#pragma once
#include <memory>
#include <optional>
#include <vector>
#include <glm/vec3.hpp>

#include "scene/unsupported.hpp"

namespace lumen::scene {

struct Normal;  // scene/texture.hpp
struct Object;  // scene/object.hpp

// X(Type, keyword): the projections, in the order the dump names them.
#define LUMEN_CAMERA_TYPES(X)                \
    X(Perspective, "perspective")            \
    X(Orthographic, "orthographic")          \
    X(Fisheye, "fisheye")                    \
    X(UltraWideAngle, "ultra_wide_angle")    \
    X(Omnimax, "omnimax")                    \
    X(Panoramic, "panoramic")                \
    X(Spherical, "spherical")                \
    X(Cylinder, "cylinder")                  \
    X(MeshCamera, "mesh_camera")

#define LUMEN_CAMERA_ENUM(T, keyword) T,
enum class CameraType { LUMEN_CAMERA_TYPES(LUMEN_CAMERA_ENUM) };
#undef LUMEN_CAMERA_ENUM

#define LUMEN_CAMERA_KEYWORD(T, keyword) keyword,
inline constexpr const char* kCameraKeywords[] = {LUMEN_CAMERA_TYPES(LUMEN_CAMERA_KEYWORD)};
#undef LUMEN_CAMERA_KEYWORD

struct Camera {
    CameraType type = CameraType::Perspective;
    glm::dvec3 location{0, 0, 0};
    glm::dvec3 direction{0, 0, 1};
    glm::dvec3 up{0, 1, 0};
    glm::dvec3 right{1.33, 0, 0};
    // The field in degrees of the projections that take one (fisheye, ultra_wide_angle,
    // cylinder: default 90; spherical: horizontal 360 and vertical 180, half the horizontal
    // when only that is given). Perspective and orthographic fold `angle` into direction.
    double angle = 90;
    double vertical_angle = 180;
    int cylinder_type = 1;  // 1..4
    // `normal { }`: perturbs each ray's direction, evaluated at the projection's own
    // coordinates of the sample.
    std::shared_ptr<const Normal> normal;
    // mesh_camera { rays distribution mesh... }: each sample's rays start on the faces of these
    // meshes (world transforms included); location.z and direction.z as written say how far
    // along the face normal a ray starts and whether it runs backwards.
    struct MeshRays {
        int rays = 1;
        // 0: ray k on mesh k; 1: meshes joined; 2: meshes side by side; 3: the pixel's place
        // in the first mesh's uv map (texture baking)
        int distribution = 0;
        std::vector<std::shared_ptr<const Object>> meshes;
        double offset = 0;     // location.z
        bool reverse = false;  // direction.z < 0
        bool smooth = false;   // distribution 3: rays along the interpolated vertex normals
    };
    std::optional<MeshRays> mesh;
    // Focal blur (`aperture` not 0 and `blur_samples` above 0): each sample averages rays from
    // a disc of diameter `aperture` around the location, all aimed at the point the unblurred
    // ray meets at `focal_distance` along the view direction, until the colour's variance is
    // below `variance` with `confidence` or `max_samples` rays are traced.
    struct FocalBlur {
        double aperture = 0;
        int min_samples = 0, max_samples = 0;
        double confidence = 0.9, variance = 1.0 / 10000;
        double focal_distance = 1;  // |focal_point - location|, |direction| by default
    };
    std::optional<FocalBlur> blur;
    std::optional<Unsupported> unsupported;  // e.g. a mesh_camera distribution
    SourceLoc loc;
};

}  // namespace lumen::scene

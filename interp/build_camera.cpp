// camera { } with POV's fix-up order, so the renderer only maps
// pixels to rays.
#include <cmath>
#include <iterator>
#include <optional>

#include <glm/geometric.hpp>

#include "interp/build_common.hpp"

namespace lumen::interp {

namespace {

constexpr int kMaxBlurSamples = 65536;

const std::vector<std::string>& camera_keywords() {
    static const std::vector<std::string> k = [] {
        std::vector<std::string> v = transform_keywords();
        v.insert(v.end(), std::begin(scene::kCameraKeywords), std::end(scene::kCameraKeywords));
        for (const char* w : {"location", "direction", "up", "right", "sky", "look_at", "angle",
                              "focal_point", "aperture", "blur_samples", "confidence",
                              "variance", "normal"})
            v.push_back(w);
        return v;
    }();
    return k;
}

// The projection a keyword names (perspective, fisheye, cylinder, ...), if any.
std::optional<scene::CameraType> camera_type(const std::string& w) {
    for (size_t i = 0; i < std::size(scene::kCameraKeywords); ++i)
        if (w == scene::kCameraKeywords[i]) return static_cast<scene::CameraType>(i);
    return std::nullopt;
}

bool folds_angle(scene::CameraType t) {
    return t == scene::CameraType::Perspective || t == scene::CameraType::Orthographic;
}

// Where the camera vectors were written (the camera block when they were not).
struct VectorLocs {
    SourceLoc direction, up, right;
};

bool parallel(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(glm::cross(a, b)) <= 1e-9 * glm::length(a) * glm::length(b);
}

// Step 6: the final direction, up and right must span space, or pixels cannot be mapped to
// distinct rays (POV renders a black or smeared image; lumen reports the cause instead).
void check_basis(ItemCursor& cur, const scene::Camera& cam, const VectorLocs& at) {
    if (cam.type == scene::CameraType::MeshCamera) return;
    for (const glm::dvec3& x : {cam.location, cam.direction, cam.up, cam.right})
        if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
            cur.fail(cam.loc, "camera vectors must be finite");
    if (!(glm::length(cam.direction) > 0)) cur.fail(at.direction, "camera direction is a zero vector");
    if (!(glm::length(cam.up) > 0)) cur.fail(at.up, "camera up is a zero vector");
    if (!(glm::length(cam.right) > 0)) cur.fail(at.right, "camera right is a zero vector");
    if (parallel(cam.up, cam.direction))
        cur.fail(at.up, "camera up is parallel to the camera direction");
    if (parallel(cam.right, cam.direction))
        cur.fail(at.right, "camera right is parallel to the camera direction");
    if (parallel(cam.up, cam.right)) cur.fail(at.up, "camera up is parallel to camera right");
}

}  // namespace

// mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { } ... [smooth] }, with POV-Ray's rules
// on how many rays each distribution takes.
scene::Camera::MeshRays read_mesh_camera(BuildContext& ctx, const BlockValue& block) {
    ItemCursor cur(ctx, block);
    scene::Camera::MeshRays m;
    const double rays = cur.expect_float("mesh_camera");
    const SourceLoc rays_loc = cur.here();
    const double dist = cur.expect_float("the number of rays");
    const SourceLoc dist_loc = cur.here();
    cur.optional_float();  // the maximum distance: POV-Ray reads it and does not use it
    bool smooth = false;
    while (!cur.at_end()) {
        const Item& item = cur.next();
        if (item.kind == Item::Kind::Keyword && item.keyword == "smooth") {
            smooth = true;
        } else if (item.kind == Item::Kind::Value && item.value.is<scene::ObjectPtr>() &&
                   std::holds_alternative<scene::Mesh>(item.value.as<scene::ObjectPtr>()->shape)) {
            m.meshes.push_back(item.value.as<scene::ObjectPtr>());
        } else {
            cur.fail(item.loc, "mesh_camera takes mesh objects and 'smooth', found " +
                                   describe_item(item));
        }
    }
    m.rays = int(rays);
    m.distribution = int(dist);
    if (!(rays >= 1)) cur.fail(rays_loc, "mesh_camera needs at least one ray per pixel");
    if (!(dist >= 0 && dist < 4)) cur.fail(dist_loc, "mesh_camera distribution must be 0, 1, 2 or 3");
    if (m.meshes.empty()) cur.fail(block.loc, "mesh_camera needs a mesh");
    if (m.distribution >= 2 && m.rays != 1)
        cur.fail(rays_loc, "mesh_camera distributions 2 and 3 take one ray per pixel");
    if (m.distribution == 0 && size_t(m.rays) > m.meshes.size())
        cur.fail(rays_loc, "mesh_camera distribution 0 needs a mesh for each ray");
    if (m.distribution == 3 && m.meshes.size() > 1)
        cur.warn(block.loc, "mesh_camera distribution 3 uses only the first mesh");
    if (smooth && m.distribution != 3) cur.warn(block.loc, "mesh_camera 'smooth' is only for distribution 3");
    m.smooth = smooth && m.distribution == 3;
    return m;
}

scene::Camera build_camera(ItemCursor& cur) {
    scene::Camera cam;
    if (cur.next_is<std::shared_ptr<const scene::Camera>>())
        cam = *cur.next().value.as<std::shared_ptr<const scene::Camera>>();
    cam.loc = cur.block_loc();
    glm::dvec3 sky{0, 1, 0}, look_at{0, 0, 1};
    bool have_look_at = false, have_up = false, have_right = false, type_given = false;
    std::optional<double> angle, vertical_angle;
    SourceLoc angle_loc;
    // Focal blur: a declared camera's settings carry over to a copy.
    const bool had_blur = cam.blur.has_value();
    scene::Camera::FocalBlur blur = cam.blur.value_or(scene::Camera::FocalBlur{});
    cam.blur.reset();
    std::optional<glm::dvec3> focal_point;
    VectorLocs at{cam.loc, cam.loc, cam.loc};
    scene::Transform transform;
    auto unsupported = [&](const std::string& f, SourceLoc loc) {
        if (!cam.unsupported) cam.unsupported = scene::Unsupported{f, loc};
    };
    while (!cur.at_end()) {
        const Item& item = cur.next();
        scene::Transform t;
        if (read_transform(cur, item, t)) {  // gathered and applied last (step 5)
            transform = transform.then(t);
            continue;
        }
        if (item.kind == Item::Kind::Value && item.value.is<scene::NormalPtr>()) {
            cam.normal = item.value.as<scene::NormalPtr>();
            if (cam.normal->pattern.unsupported)
                unsupported(cam.normal->pattern.unsupported->feature, cam.normal->pattern.unsupported->loc);
            continue;
        }
        if (const BlockValue* b = block_of(item, "mesh_camera")) {
            cam.type = scene::CameraType::MeshCamera;
            cam.mesh = read_mesh_camera(cur.ctx(), *b);
            type_given = true;
            continue;
        }
        if (item.kind != Item::Kind::Keyword) cur.fail_unexpected(item, camera_keywords());
        const std::string& w = item.keyword;
        if (const std::optional<scene::CameraType> type = camera_type(w)) {
            cam.type = *type;
            cam.mesh.reset();
            type_given = true;
            if (w == "cylinder") {
                const double n = cur.expect_float(w);  // truncated, as POV does
                if (!(n >= 1 && n < 5)) cur.fail(item.loc, "cylinder camera type must be 1, 2, 3 or 4");
                cam.cylinder_type = int(n);
            }
        } else if (w == "location") cam.location = cur.expect_vector(w);
        else if (w == "direction") {
            cam.direction = cur.expect_vector(w);
            at.direction = item.loc;
        } else if (w == "up") {
            cam.up = cur.expect_vector(w);
            have_up = true;
            at.up = item.loc;
        } else if (w == "right") {
            cam.right = cur.expect_vector(w);
            have_right = true;
            at.right = item.loc;
        }
        else if (w == "sky") sky = cur.expect_vector(w);
        else if (w == "look_at") { look_at = cur.expect_vector(w); have_look_at = true; }
        else if (w == "angle") {
            angle = cur.expect_float(w);
            angle_loc = item.loc;
            vertical_angle = cur.optional_float();  // spherical cameras
        }
        else if (w == "focal_point") focal_point = cur.expect_vector(w);
        else if (w == "aperture") blur.aperture = cur.expect_float(w);
        else if (w == "blur_samples") {
            // `blur_samples [MIN,] MAX`: one number is the maximum, with no minimum.
            // Each count is truncated and at least 1 (measured: 0 and negatives are POV's
            // "Illegal number of focal blur samples"); lumen also bounds the maximum.
            auto count = [&](double v) {
                if (!(v >= 1)) cur.fail(item.loc, "illegal number of focal blur samples (at least 1)");
                if (v > kMaxBlurSamples)
                    cur.fail(item.loc, "too many focal blur samples (at most " +
                                           std::to_string(kMaxBlurSamples) + ")");
                return int(v);
            };
            const int first = count(cur.expect_float(w));
            if (std::optional<double> second = cur.optional_float()) {
                blur.min_samples = first;
                blur.max_samples = count(*second);
            } else {
                blur.min_samples = 0;
                blur.max_samples = first;
            }
            if (blur.min_samples > blur.max_samples)
                cur.fail(item.loc, "focal blur samples minimum must not be larger than maximum");
        } else if (w == "confidence") blur.confidence = cur.expect_float(w);
        else if (w == "variance") blur.variance = cur.expect_float(w);
        else cur.fail_unexpected(item, camera_keywords());
    }
    if (cam.mesh) {  // only location.z and direction.z as written count (measured)
        cam.mesh->offset = cam.location.z;
        cam.mesh->reverse = cam.direction.z < -1e-10;
    }
    if (!(glm::length(cam.direction) > 0))
        cur.fail(at.direction, "camera direction is a zero vector");
    // The projections that keep their angle (measured defaults: 90, spherical 360 by 180).
    if (cam.type == scene::CameraType::Spherical) {
        cam.angle = angle.value_or(360);
        cam.vertical_angle = vertical_angle.value_or(angle ? *angle / 2 : 180);
    } else if (angle && !folds_angle(cam.type)) {
        if (cam.type == scene::CameraType::Cylinder && *angle < 0)
            cur.fail(angle_loc, "camera angle must not be negative");
        cam.angle = *angle;
    }
    // Step 2: angle is the full horizontal field of view along `right`.
    if (angle && folds_angle(cam.type)) {
        if (!(*angle > 0 && *angle < 180))
            cur.fail(angle_loc, "camera angle must be between 0 and 180 degrees");
        double half = *angle * M_PI / 360.0;
        cam.direction = glm::normalize(cam.direction) * glm::length(cam.right) /
                        (2.0 * std::tan(half));
    }
    // Step 3: look_at turns the camera, keeping the vectors' lengths and handedness.
    if (have_look_at) {
        double dl = glm::length(cam.direction), ul = glm::length(cam.up),
               rl = glm::length(cam.right);
        double handed = glm::dot(glm::cross(cam.up, cam.direction), cam.right);
        glm::dvec3 d = look_at - cam.location;
        if (glm::length(d) == 0.0) cur.fail(cam.loc, "camera look_at equals its location");
        d = glm::normalize(d);
        glm::dvec3 r = glm::cross(sky, d);
        if (glm::length(r) < 1e-10) {
            cur.warn(cam.loc, "camera sky is parallel to the view direction: right kept");
            r = glm::normalize(cam.right);
        } else {
            r = glm::normalize(r);
        }
        if (parallel(d, r)) cur.fail(at.right, "camera right is parallel to the camera direction");
        glm::dvec3 u = glm::normalize(glm::cross(d, r));
        cam.direction = d * dl;
        cam.right = r * (handed > 0 ? rl : -rl);
        cam.up = u * ul;
    }
    // Step 4: an orthographic camera sized by its look_at distance.
    // A declared camera used again (`camera { Camera_1 }`) arrives sized: only this block's
    // `orthographic` sizes it (measured: POV renders such a copy unchanged).
    if (cam.type == scene::CameraType::Orthographic && type_given &&
        ((!have_up && !have_right) || angle)) {
        double k = glm::length(look_at - cam.location) / glm::length(cam.direction);
        cam.right *= k;
        cam.up *= k;
    }
    // Step 5: transforms last.
    cam.location = transform.point(cam.location);
    cam.direction = transform.vector(cam.direction);
    cam.up = transform.vector(cam.up);
    cam.right = transform.vector(cam.right);
    check_basis(cur, cam, at);
    if (blur.aperture != 0 && blur.max_samples > 0) {
        if (focal_point)
            blur.focal_distance = glm::length(transform.point(*focal_point) - cam.location);
        else if (!had_blur)
            blur.focal_distance = glm::length(cam.direction);
        if (!(blur.focal_distance > 0) || !std::isfinite(blur.focal_distance))
            blur.focal_distance = glm::length(cam.direction);
        cam.blur = blur;
    }
    return cam;
}

}  // namespace lumen::interp

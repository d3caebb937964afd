// Embree 3 behind a mesh's queries (mesh_embree.hpp).
//
// Embree holds the vertices in single precision, less the centre of the mesh's box (so its
// precision follows the mesh's size, not its distance from the origin), and decides which
// triangles a ray meets: in its robust mode its test is watertight along edges, so a ray
// through a shared edge meets one of the two (without it, a sixth of the rays aimed at a
// grid's edges slipped through). The triangle's plane in double precision then gives the
// distance, as lumen's own test would to rounding (no edge test there: it would turn down
// Embree's choice within rounding of an edge and open a crack). A candidate outside
// (tmin, tmax) in double precision is passed over: Embree searches over an interval widened
// by a float step on each side, and a ray leaving a surface may meet its own triangle.
// - nearest: Embree's nearest candidate is confirmed; where it falls outside (tmin, tmax)
//   the search runs again with a filter that confirms every candidate;
// - any and crossings: the filter confirms every candidate; crossings rejects them all, so
//   Embree visits every one, and counts each triangle once.
#include "render/shapes/mesh_embree.hpp"

#ifdef LUMEN_HAVE_EMBREE
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include <embree3/rtcore.h>

#include "base/shared_library.hpp"

namespace lumen::render {

namespace {

// Embree's functions lumen calls, from the library opened at the first mesh that wants it
// (base/shared_library.hpp): a scene without big meshes does not load Embree and TBB.
#define LUMEN_EMBREE_FUNCTIONS(X)                                                           \
    X(rtcNewDevice) X(rtcReleaseDevice) X(rtcGetDeviceError) X(rtcNewScene)                 \
    X(rtcSetSceneFlags) X(rtcCommitScene) X(rtcReleaseScene) X(rtcNewGeometry)              \
    X(rtcSetNewGeometryBuffer) X(rtcCommitGeometry) X(rtcAttachGeometry)                   \
    X(rtcReleaseGeometry) X(rtcIntersect1) X(rtcOccluded1)

LUMEN_LIBRARY_API(Embree, LUMEN_EMBREE_FUNCTIONS)

// The functions, or null where the library cannot be opened or lacks one of them (looked up
// once: every ray calls through them).
const Embree* embree() {
    static const Embree* api = [] {
        std::string why;
        return base::library_api<Embree>(LUMEN_EMBREE_LIBRARY, why);
    }();
    return api;
}

// One device for the process, on the calling thread only ("threads=1": lumen's own threads
// trace, and builds run where the scene is prepared).
RTCDevice device() {
    struct Holder {
        RTCDevice d = embree() ? embree()->rtcNewDevice("threads=1") : nullptr;
        ~Holder() {
            if (d) embree()->rtcReleaseDevice(d);
        }
    };
    static Holder holder;
    return holder.d;
}

float below(double x) {
    const float f = float(x);
    return double(f) > x ? std::nextafter(f, -FLT_MAX) : f;
}
float above(double x) {
    if (!(x < double(FLT_MAX))) return INFINITY;
    const float f = float(x);
    return double(f) < x ? std::nextafter(f, FLT_MAX) : f;
}

// The intersect context a filter reads its query from.
struct Query {
    RTCIntersectContext base;  // first: Embree passes a pointer to it
    const EmbreeMesh::Plane* planes;
    const LocalRay* ray;
    double tmin, tmax;
    EmbreeMesh::Found found;
    bool any = false;
    int crossings = 0;
    uint32_t seen[16];
    int seen_count = 0;

    Query(const EmbreeMesh::Plane* p, const LocalRay& r, double t0, double t1,
          RTCFilterFunctionN filter)
        : planes(p), ray(&r), tmin(t0), tmax(t1) {
        rtcInitIntersectContext(&base);
        base.filter = filter;
    }
};

// The distance to triangle `tri`'s plane in double precision, if within (tmin, tmax); Embree's
// weights, brought back into the triangle, for the normal and uv blends.
bool confirm(const Query& q, uint32_t tri, float u, float v, EmbreeMesh::Found& f) {
    const EmbreeMesh::Plane& p = q.planes[tri];
    const double along = glm::dot(p.n, q.ray->d);
    if (along == 0) return false;  // in the plane, in double precision
    f.t = (p.d - glm::dot(p.n, q.ray->o)) / along;
    if (!(f.t > q.tmin && f.t < q.tmax)) return false;
    f.tri = tri;
    f.u = std::clamp(double(u), 0.0, 1.0);
    f.v = std::clamp(double(v), 0.0, 1.0 - f.u);
    f.normal = p.n;
    return true;
}
bool confirm(const Query& q, const RTCFilterFunctionNArguments* args, EmbreeMesh::Found& f) {
    return confirm(q, RTCHitN_primID(args->hit, args->N, 0), RTCHitN_u(args->hit, args->N, 0),
                   RTCHitN_v(args->hit, args->N, 0), f);
}

// Accepts a candidate only where confirm() does (nearest and any).
void confirm_filter(const RTCFilterFunctionNArguments* args) {
    Query& q = *reinterpret_cast<Query*>(args->context);
    EmbreeMesh::Found f;
    if (!confirm(q, args, f)) {
        args->valid[0] = 0;
        return;
    }
    q.found = f;
    q.any = true;
}

// Counts each candidate confirm() takes, once, and rejects them all.
void crossing_filter(const RTCFilterFunctionNArguments* args) {
    Query& q = *reinterpret_cast<Query*>(args->context);
    args->valid[0] = 0;
    EmbreeMesh::Found f;
    if (!confirm(q, args, f)) return;
    const uint32_t tri = f.tri;
    // A triangle may be met in more than one leaf: count it once.
    if (std::find(q.seen, q.seen + q.seen_count, tri) != q.seen + q.seen_count) return;
    if (q.seen_count < 16) q.seen[q.seen_count++] = tri;
    ++q.crossings;
}

// False for NaN and infinities too.
bool fits_float(const glm::dvec3& v) {
    return std::abs(v.x) < 1e30 && std::abs(v.y) < 1e30 && std::abs(v.z) < 1e30;
}

}  // namespace

bool EmbreeMesh::built_in() { return device() != nullptr; }

std::unique_ptr<EmbreeMesh> EmbreeMesh::build(const std::vector<glm::dvec3>& vertices,
                                              const std::vector<uint32_t>& index,
                                              const std::vector<TriangleCore>& tris) {
    RTCDevice dev = device();
    if (!dev || tris.empty() || index.size() != 3 * tris.size()) return nullptr;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (uint32_t i : index) {
        if (i >= vertices.size() || !fits_float(vertices[i])) return nullptr;
        lo = glm::min(lo, vertices[i]), hi = glm::max(hi, vertices[i]);
    }
    std::unique_ptr<EmbreeMesh> out(new EmbreeMesh);
    out->centre_ = 0.5 * (lo + hi);
    out->planes_.reserve(tris.size());
    for (const TriangleCore& t : tris) {
        const glm::dvec3 n = glm::cross(t.e1, t.e2);
        out->planes_.push_back({n, glm::dot(n, t.p0)});
    }
    RTCScene scene = embree()->rtcNewScene(dev);
    if (!scene) return nullptr;
    embree()->rtcSetSceneFlags(scene,
                               RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION | RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geom = embree()->rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(embree()->rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
    auto* ix = static_cast<uint32_t*>(embree()->rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), tris.size()));
    if (!v || !ix) {
        embree()->rtcReleaseGeometry(geom);
        embree()->rtcReleaseScene(scene);
        return nullptr;
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        // Vertices no face uses may lie anywhere: Embree never reads them.
        const glm::dvec3 p = fits_float(vertices[i]) ? vertices[i] - out->centre_ : glm::dvec3(0);
        for (int k = 0; k < 3; ++k) v[3 * i + k] = float(p[k]);
    }
    std::copy(index.begin(), index.end(), ix);
    embree()->rtcCommitGeometry(geom);
    embree()->rtcAttachGeometry(scene, geom);
    embree()->rtcReleaseGeometry(geom);
    embree()->rtcCommitScene(scene);
    if (embree()->rtcGetDeviceError(dev) != RTC_ERROR_NONE) {
        embree()->rtcReleaseScene(scene);
        return nullptr;
    }
    out->scene_ = scene;
    return out;
}

EmbreeMesh::~EmbreeMesh() {
    if (scene_) embree()->rtcReleaseScene(static_cast<RTCScene>(scene_));
}

namespace {

// Embree's ray: from the origin less the mesh's centre; false for rays single precision
// cannot hold.
bool embree_ray(const LocalRay& r, const glm::dvec3& centre, double tmin, double tmax,
                RTCRay& ray) {
    const glm::dvec3 o = r.o - centre;
    if (!fits_float(o) || !fits_float(r.d)) return false;  // NaN and infinities included
    ray.org_x = float(o.x), ray.org_y = float(o.y), ray.org_z = float(o.z);
    ray.dir_x = float(r.d.x), ray.dir_y = float(r.d.y), ray.dir_z = float(r.d.z);
    ray.tnear = std::max(0.0f, below(tmin));
    ray.tfar = above(tmax);
    ray.time = 0;
    ray.mask = ~0u;
    ray.id = 0;
    ray.flags = 0;
    return ray.tnear <= ray.tfar;
}

}  // namespace

bool EmbreeMesh::nearest(const LocalRay& r, double tmin, double tmax, Found& out) const {
    Query q(planes_.data(), r, tmin, tmax, nullptr);
    RTCRayHit rh;
    if (!embree_ray(r, centre_, tmin, tmax, rh.ray)) return false;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    embree()->rtcIntersect1(static_cast<RTCScene>(scene_), &q.base, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    if (confirm(q, rh.hit.primID, rh.hit.u, rh.hit.v, out)) return true;
    // Outside (tmin, tmax) in double precision: confirm every candidate.
    q.base.filter = confirm_filter;
    embree_ray(r, centre_, tmin, tmax, rh.ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    embree()->rtcIntersect1(static_cast<RTCScene>(scene_), &q.base, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID &&
           confirm(q, rh.hit.primID, rh.hit.u, rh.hit.v, out);
}

bool EmbreeMesh::any(const LocalRay& r, double tmin, double tmax, Found& out) const {
    Query q(planes_.data(), r, tmin, tmax, confirm_filter);
    RTCRay ray;
    if (!embree_ray(r, centre_, tmin, tmax, ray)) return false;
    embree()->rtcOccluded1(static_cast<RTCScene>(scene_), &q.base, &ray);
    if (!q.any) return false;
    out = q.found;
    return true;
}

int EmbreeMesh::crossings(const LocalRay& r) const {
    Query q(planes_.data(), r, 0, INFINITY, crossing_filter);
    RTCRayHit rh;
    if (!embree_ray(r, centre_, 0, INFINITY, rh.ray)) return 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    embree()->rtcIntersect1(static_cast<RTCScene>(scene_), &q.base, &rh);
    return q.crossings;
}

}  // namespace lumen::render

#else  // without Embree: no mesh is built with it

namespace lumen::render {

bool EmbreeMesh::built_in() { return false; }
std::unique_ptr<EmbreeMesh> EmbreeMesh::build(const std::vector<glm::dvec3>&,
                                              const std::vector<uint32_t>&,
                                              const std::vector<TriangleCore>&) {
    return nullptr;
}
EmbreeMesh::~EmbreeMesh() = default;
bool EmbreeMesh::nearest(const LocalRay&, double, double, Found&) const { return false; }
bool EmbreeMesh::any(const LocalRay&, double, double, Found&) const { return false; }
int EmbreeMesh::crossings(const LocalRay&) const { return 0; }

}  // namespace lumen::render

#endif

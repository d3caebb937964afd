#include "render/tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "base/diagnostics.hpp"
#include "render/fog.hpp"
#include "render/rainbow.hpp"
#include "render/frame.hpp"
#include "render/media.hpp"
#include "render/normal.hpp"
#include "render/pattern.hpp"
#include "render/photons/photon_flags.hpp"
#include "render/pigment.hpp"
#include "render/shadows.hpp"
#include "render/shapes/blob.hpp"
#include "render/sky.hpp"
#include "render/texture_layers.hpp"

namespace lumen::render {
namespace {

constexpr double kMinDepth = 1e-4;       // every ray ignores nearer hits
constexpr double kMaxDistance = 1e7;     // depth reported for rays that escape
constexpr int kMaxSkippedSurfaces = 64;  // no_image / no_reflection objects passed through

double grey(const glm::dvec3& c) { return 0.297 * c.x + 0.589 * c.y + 0.114 * c.z; }

double max_abs(const glm::dvec3& c) {
    return std::max({std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
}

bool object_has_media(const scene::Object& o) {
    if (o.interior && !o.interior->media.empty()) return true;
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const auto& child : csg->children)
            if (child && object_has_media(*child)) return true;
    return false;
}

bool scene_has_interior_media(const scene::Scene& scene) {
    for (const auto& o : scene.objects)
        if (o && object_has_media(*o)) return true;
    return false;
}

// Where a ray goes when it crosses the surface of `hit`'s object: the new interior list and
// the ratio of refractive indices.
double cross_surface(const InteriorList& before, const Hit& hit, InteriorList& after) {
    return cross_interface(before, hit.interior_id, hit.interior, hit.hollow, after);
}

// Single patterned texture whose entries are shaded separately and blended.
// The hit as the surface patterns (slope, aoi) see it: the normal turned to face the ray.
SurfacePoint surface_point(const Ray& ray, const Hit& hit) {
    glm::dvec3 n = hit.normal;
    if (hit.pattern_normal) n = *hit.pattern_normal;
    else if (glm::dot(n, ray.dir) > 0) n = -n;
    return {hit.point, n, ray.dir, hit.uv};
}

bool is_texture_map(const scene::LayeredTexture* t) {
    return t && t->size() == 1 && t->front() &&
           !t->front()->pattern.is_plain() &&
           !t->front()->texture_map.empty();
}

}  // namespace

struct Tracer::Context {
    int level = 0;
    double weight = 1;
    const InteriorList* interiors = nullptr;  // the interiors the ray travels in
    RayKind kind = RayKind::Image;
    bool continued = false;  // passes through an ior-1 surface without using a trace level
};

Tracer::Tracer(const RenderFrame& frame, const TraceOptions& options)
    : scene_(frame.scene()), geometry_(frame.geometry()), options_(options) {
    init(frame.lights());
    camera_interiors_ = frame.geometry().interiors_around(scene_.camera.location);
}

Tracer::Tracer(const scene::Scene& scene, const Intersector& geometry, const TraceOptions& options)
    : scene_(scene), geometry_(geometry), options_(options),
      own_lights_(prepare_lights(scene.lights)) {
    check_supported(scene);
    init(own_lights_);
}

void Tracer::init(const std::vector<LightSource>& lights) {
    const scene::Scene& scene = scene_;
    const TraceOptions& options = options_;
    env_.lights = &lights;
    env_.geometry = &geometry_;
    env_.ambient_light = scene.globals.ambient_light;
    env_.irid_wavelength = scene.globals.irid_wavelength;
    env_.fogs = &scene.fogs;
    env_.noise_generator = noise::resolve_generator(0, scene.globals.noise_generator);
    env_.ambient_off = scene.globals.radiosity.has_value() && scene.language_version >= 3.7 &&
                       options.quality >= 9;
    env_.quality = options.quality;
    env_.photon_map = options.photons && !options.photons->surface.empty();
    if (options.photons && !options.photons->media.empty()) {
        env_.media_photons = &options.photons->media;
        env_.media_gather = options.photons->media_gather;
    }
    max_level_ = std::clamp(scene.globals.max_trace_level, 1, 256);
    adc_bailout_ = scene.globals.adc_bailout;
    legacy_opacity_ = scene.language_version < 3.7;
    for (const auto& m : scene.atmosphere) atmosphere_.push_back(m.get());
    media_ = !atmosphere_.empty() || scene_has_interior_media(scene);
    env_.atmosphere = &atmosphere_;
}

RayColour Tracer::trace_primary(const Ray& ray, ThreadState& state) const {
    Context ctx;
    ctx.interiors = &camera_interiors_;
    double depth = 0;
    return trace(ray, ctx, state, &depth);
}

bool Tracer::find_hit(const Ray& ray, RayKind kind, Hit& hit) const {
    double t_min = kMinDepth;
    for (int i = 0; i < kMaxSkippedSurfaces; ++i) {
        if (!geometry_.intersect(ray, t_min, std::numeric_limits<double>::infinity(), hit, Query::All))
            return false;
        // Flags after CSG inheritance (a CSG's no_image hides all its children).
        const bool invisible = (kind == RayKind::Image && hit.no_image) ||
                               (kind == RayKind::Reflection && hit.no_reflection);
        if (!invisible) return true;
        t_min = hit.t;
    }
    return false;
}

RayColour Tracer::trace(const Ray& ray, const Context& ctx, ThreadState& state,
                        double* depth) const {
    *depth = kMaxDistance;
    if (ctx.level >= max_level_ || ctx.weight < adc_bailout_) return {};
    Context here = ctx;
    if (!ctx.continued) ++here.level;
    here.continued = false;
    ++state.counters.rays;

    Hit hit;
    RayColour c;
    if (find_hit(ray, ctx.kind, hit)) {
        *depth = hit.t;
        hit.texture = facing_texture(hit, ray.dir);
        glm::dvec3 pattern_normal = surface_point(ray, hit).normal;
        hit.pattern_normal = &pattern_normal;
        c = shade(ray, hit, {hit.point, NormalFrame::none()}, here, state);
    } else {
        c = sky(ray.dir);
    }
    // Rainbows and media see a ray that hits nothing as POV-Ray's 2e10 long.
    const double atmosphere_depth = *depth == kMaxDistance ? kMediaEscapeDepth : *depth;
    if (!scene_.rainbows.empty()) apply_rainbows(c, ray, atmosphere_depth, *ctx.interiors, state);
    if (media_) apply_media(c, ray, atmosphere_depth, *depth != kMaxDistance, *ctx.interiors, state);
    if (!scene_.fogs.empty()) apply_fog(c, ray, *depth, *ctx.interiors);  // no call per ray without fog
    return c;
}

RayColour Tracer::shade(const Ray& ray, const Hit& hit, const TexturePoint& at, const Context& ctx,
                        ThreadState& state) const {
    if (hit.textured_blob) return shade_blob(ray, hit, at, ctx, state);
    const scene::LayeredTexture* texture = hit.texture;
    if (!is_texture_map(texture)) return shade_layers(ray, hit, texture, at, ctx, state);
    // texture_map: shade both neighbouring entries, at the map's pattern point and in its
    // frame, and blend.
    const scene::Texture& t = *texture->front();
    const SurfacePoint surface = surface_point(ray, hit);
    const TexturePoint tp{pattern_point(t.pattern, source_point(t.pattern, at.point, &surface)),
                          at.frame.then(NormalFrame::of(t.pattern))};
    auto entry = [&](int i, double w) {
        Context sub = ctx;
        sub.weight *= w;
        Hit h = hit;
        h.texture = &t.texture_map[i].item;
        return shade(ray, h, tp, sub, state);
    };
    if (std::holds_alternative<scene::pattern::Average>(t.pattern.kind)) {
        // average: every entry shaded and weighted by its value (a total of 0 gives black),
        // however light (POV shows a 0.3% entry).
        RayColour out;
        const double total = scene::average_total(t.texture_map);
        if (total == 0) return out;
        for (int i = 0; i < int(t.texture_map.size()); ++i) {
            const double w = t.texture_map[i].value / total;
            if (w == 0) continue;
            const RayColour c = entry(i, std::fabs(w));
            out.rgb += w * c.rgb;
            out.transmit += w * c.transmit;
        }
        return out;
    }
    const BlendWeights b =
        blend_weights(t.texture_map, pattern_value_at(t.pattern, tp.point, &surface));
    if (b.upper_weight == 0) return entry(b.lower, 1.0);
    RayColour out;
    const double ws[2] = {1 - b.upper_weight, b.upper_weight};
    const int idx[2] = {b.lower, b.upper};
    // Both entries are shaded however small a weight (POV does: a 0.4% entry shows in a dark
    // pixel's sRGB level); only the rays they spawn obey adc_bailout. The upper entry first,
    // as POV-Ray: the lower one's slope patterns see the normal the upper one perturbed.
    for (int k = 1; k >= 0; --k) {
        const RayColour c = entry(idx[k], ws[k]);
        out.rgb += ws[k] * c.rgb;
        out.transmit += ws[k] * c.transmit;
    }
    return out;
}

// A blob with textured components: each texture present at the point shaded and weighted by
// its components' share of the density there (POV-Ray's blob texture blending); components
// without a texture of their own count for the blob's.
RayColour Tracer::shade_blob(const Ray& ray, const Hit& hit, const TexturePoint& at,
                             const Context& ctx, ThreadState& state) const {
    constexpr int kMaxTextures = 64;  // beyond this many at one point, the rest join the last
    const scene::LayeredTexture* textures[kMaxTextures];
    double weights[kMaxTextures];
    int n = 0;
    double total = 0;
    const BlobShape& blob = *hit.textured_blob;
    for_each_blob_density(blob, hit.local_point, [&](int component, double w) {
        const scene::LayeredTexture* t = blob.textures[component];
        if (!t) t = hit.texture;
        total += w;
        for (int i = 0; i < n; ++i)
            if (textures[i] == t) { weights[i] += w; return; }
        if (n == kMaxTextures) { weights[n - 1] += w; return; }
        textures[n] = t;
        weights[n++] = w;
    });
    Hit h = hit;
    h.textured_blob = nullptr;
    if (n == 0 || !(total > 0)) return shade(ray, h, at, ctx, state);
    RayColour out;
    for (int i = 0; i < n; ++i) {
        const double w = weights[i] / total;
        Context sub = ctx;
        sub.weight *= w;
        h.texture = textures[i];
        const RayColour c = shade(ray, h, at, sub, state);
        out.rgb += w * c.rgb;
        out.transmit += w * c.transmit;
    }
    return out;
}

RayColour Tracer::shade_layers(const Ray& ray, const Hit& hit, const scene::LayeredTexture* texture,
                               const TexturePoint& at, const Context& ctx,
                               ThreadState& state) const {
    const glm::dvec3 d = ray.dir;
    glm::dvec3 raw_n = hit.normal;
    if (glm::dot(raw_n, d) > 0) raw_n = -raw_n;  // every surface is two-sided

    ResolvedLayers layers;
    const SurfacePoint surface = surface_point(ray, hit);
    resolve_layers(texture, at.point, layers, &surface);

    const int quality = options_.quality;
    const bool double_illuminate = hit.double_illuminate;

    // Relative IOR across this surface, only needed by fresnel reflection.
    InteriorList beyond;
    const double eta = cross_surface(*ctx.interiors, hit, beyond);
    const double fresnel_ior = fresnel_relative_ior(*ctx.interiors, hit.interior_id, eta);

    struct PendingReflection {
        glm::dvec3 colour, normal;
        double weight, exponent;
    };
    PendingReflection reflections[ResolvedLayers::kMax];
    int n_reflections = 0;
    glm::dvec3 top_reflectivity(0);
    bool top_reflects = false;  // reflections[0] belongs to the top layer

    RayColour out;
    glm::dvec3 filter(1);
    glm::dvec3 top_normal = raw_n;  // refraction bends about the top layer's normal
    double top_film = 0;            // the top layer's irid film thickness
    glm::dvec3 indirect(0);  // fetched once per hit, shared by the layers
    bool have_indirect = false;
    const bool photons = env_.photon_map && collects_photons(hit.photons);
    thread_local GatheredPhotons gathered;  // once per hit, used before any ray is spawned
    bool have_photons = false;
    for (int i = 0; i < layers.count(); ++i) {
        const ResolvedLayer& layer = layers[i];
        SurfaceSample s;
        s.point = hit.point;
        s.view = d;
        // Each layer perturbs the surface normal on its own (POV applies normals from +Q8).
        s.normal = layer.normal && quality >= 8
                       ? framed_normal(*layer.normal, raw_n, layer.point, at.frame.then(layer.frame))
                       : raw_n;
        if (i == 0) top_normal = s.normal;
        if (layer.normal && quality >= 8 && hit.pattern_normal) *hit.pattern_normal = s.normal;
        // POV colours a layer after perturbing its normal: a slope or aoi pigment sees the
        // normal this layer (or the last one that had a normal) left.
        scene::Colour c = layer.colour;
        if (layer.reads_normal && hit.pattern_normal && *hit.pattern_normal != surface.normal) {
            SurfacePoint now = surface;
            now.normal = *hit.pattern_normal;
            c = resolve_layer(*layer.source, at.point, &now).colour;
        }
        const glm::dvec3 rgb(c.r, c.g, c.b);
        s.raw_normal = raw_n;
        s.object = hit.object;
        s.colour = rgb;
        s.opacity = legacy_opacity_ ? 1 - (c.f * std::max({c.r, c.g, c.b}) + c.t) : 1 - c.f - c.t;
        s.finish = layer.finish;
        s.double_illuminate = double_illuminate;
        s.collects_photons = collects_photons(hit.photons);
        s.light_group = hit.light_group;
        s.global_lights = hit.global_lights;
        if (layer.finish->irid_amount > 0)  // once per layer: lights and reflection share it
            s.film_thickness = irid_thickness(*layer.finish, s.point, env_.noise_generator);
        if (i == 0) top_film = s.film_thickness;
        out.rgb += filter * local_light(s, env_, *ctx.interiors, state);
        const scene::Finish& lf = *layer.finish;
        if (photons && quality >= 5 &&
            (lf.diffuse > 0 || lf.diffuse_back > 0 || lf.phong > 0 || lf.specular > 0)) {
            if (!have_photons)
                options_.photons->surface.gather_adaptive(hit.point, raw_n, options_.photons->gather,
                                                          gathered);
            have_photons = true;
            out.rgb += filter * photon_light(s, gathered);
        }
        if (options_.indirect && layer.finish->diffuse > 0 && quality >= 9) {
            // Radiosity in place of ambient: diffuse × pigment × incident indirect light.
            if (!have_indirect) indirect = options_.indirect->incident(hit, raw_n, state);
            have_indirect = true;
            out.rgb += filter * rgb * (layer.finish->diffuse * s.opacity) * indirect;
        }

        if (quality >= 8) {
            Reflectivity r = reflectivity(*layer.finish, -glm::dot(d, s.normal), fresnel_ior, rgb);
            if (r.any() && layer.finish->irid_amount > 0) {
                // POV's film tints the reflection too, the mirror direction as the light's.
                const double cos_v = glm::dot(s.normal, d);
                r.colour *= irid_factor(*layer.finish, s.film_thickness, env_.irid_wavelength,
                                        cos_v, cos_v);
            }
            if (i == 0) top_reflectivity = r.colour, top_reflects = r.any();
            if (r.any())
                reflections[n_reflections++] = {r.colour * filter, s.normal,
                                                ctx.weight * r.weight * std::fabs(grey(filter)),
                                                layer.finish->reflection_exponent};
        }
        filter *= layer_filter(c);
        if (std::fabs(grey(filter)) <= adc_bailout_) break;
    }

    // Transmission through the surface (refraction, continued rays, total internal reflection).
    bool total_internal = false;
    const scene::Finish& top = *layers[0].finish;
    glm::dvec3 f = filter;
    if (top.conserve_energy) f *= glm::min(glm::dvec3(1), glm::dvec3(1) - top_reflectivity);
    const double trans = std::min(1.0, std::fabs(grey(f)));
    if (trans > adc_bailout_) {
        Context child = ctx;
        child.weight = ctx.weight * max_abs(f);
        double child_depth = 0;
        RayColour t;
        glm::dvec3 fade(1);
        const double refraction_eta = quality >= 6 ? eta : 1.0;
        if (refraction_eta == 1.0) {
            child.interiors = &beyond;
            child.continued = true;
            t = trace(Ray{hit.point, d}, child, state, &child_depth);
        } else {
            const glm::dvec3 nl = top_normal;
            double n = glm::dot(d, nl);
            glm::dvec3 ln;
            if (n <= 0) {
                ln = nl;
                n = -n;
            } else {
                ln = -nl;
            }
            const double k = 1 + refraction_eta * refraction_eta * (n * n - 1);
            if (k < 0) {
                total_internal = true;
                child.kind = RayKind::Reflection;
                t = trace(Ray{hit.point, reflect_direction(d, nl, raw_n)}, child, state,
                          &child_depth);
            } else {
                child.interiors = &beyond;
                const glm::dvec3 dir =
                    glm::normalize(refraction_eta * d + (refraction_eta * n - std::sqrt(k)) * ln);
                t = trace(Ray{hit.point, dir}, child, state, &child_depth);
            }
        }
        // Fade: the incoming ray crossed this object's interior for hit.t (only the light
        // passing through is faded, not the surface's own colour).
        if (hit.interior && ctx.interiors->find(hit.interior_id) >= 0)
            fade = interior_fade(*hit.interior, hit.t, false);
        if (total_internal && top.irid_amount > 0) {
            const double cos_v = glm::dot(top_normal, d);  // the film tints it as a reflection
            t.rgb *= irid_factor(top, top_film, env_.irid_wavelength, cos_v, cos_v);
        }
        out.rgb += total_internal ? fade * t.rgb : fade * t.rgb * f;
        out.transmit = grey(fade) * t.transmit * trans;
    }

    // Reflection, per layer.
    for (int i = 0; i < n_reflections; ++i) {
        const PendingReflection& r = reflections[i];
        if (total_internal && i == 0 && top_reflects) continue;  // TIR replaced it
        Context child = ctx;
        child.weight = r.weight;
        child.kind = RayKind::Reflection;
        double child_depth = 0;
        RayColour rc = trace(Ray{hit.point, reflect_direction(d, r.normal, raw_n)}, child, state,
                             &child_depth);
        if (r.exponent != 1 && r.exponent != 0)
            rc.rgb = glm::pow(glm::max(rc.rgb, glm::dvec3(0)), glm::dvec3(1 / r.exponent));
        out.rgb += r.colour * rc.rgb;
    }
    return out;
}

RayColour Tracer::sky(const glm::dvec3& dir) const {
    const scene::Colour& bg = scene_.background;
    RayColour out;
    glm::dvec3 through;
    out.rgb = sky_colour(scene_, dir, &through);
    out.transmit = options_.alpha ? (bg == scene::Colour{} ? 1.0 : bg.t) : 0.0;
    if (scene_.sky_sphere && !scene_.sky_sphere->pigments.empty()) out.transmit *= grey(through);
    return out;
}

void Tracer::apply_media(RayColour& c, const Ray& ray, double depth, bool hit,
                         const InteriorList& interiors, ThreadState& state) const {
    if (interiors.in_solid()) return;  // POV-Ray: no media while inside a solid object
    auto apply = [&](const std::vector<const scene::Media*>& media) {
        const MediaEffect e = integrate_media(media, ray, depth, true, env_, interiors, state);
        c.rgb = c.rgb * e.transmittance + e.added;
        c.transmit *= grey(e.transmittance);
    };
    if (hit && !interiors.empty()) {
        thread_local std::vector<const scene::Media*> inside;  // kept: no allocation per ray
        media_in(interiors, inside);
        if (!inside.empty()) apply(inside);
    }
    if (!atmosphere_.empty()) apply(atmosphere_);
}

void Tracer::apply_rainbows(RayColour& c, const Ray& ray, double depth,
                            const InteriorList& interiors, ThreadState& state) const {
    if (interiors.in_solid()) return;  // as fog: only through hollow space
    c.rgb = through_rainbows(scene_.rainbows, ray.dir, depth, c.rgb,  // ray.dir is unit
                             [&] { return state.uniform(); }, c.transmit);
}

void Tracer::apply_fog(RayColour& c, const Ray& ray, double depth,
                       const InteriorList& interiors) const {
    // No fog while the ray is inside a solid (non-hollow) object.
    if (scene_.fogs.empty() || interiors.in_solid()) return;
    const FogEffect e = fog_along(scene_.fogs, ray, depth, env_.noise_generator);
    c.rgb = e.added + e.attenuation * c.rgb;
    c.transmit *= e.transmit;
}

}  // namespace lumen::render

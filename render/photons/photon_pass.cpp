// Shooting (POV-Ray 3.7's rings of photons from each light at each target's bounding sphere)
// and tracing photons through reflection and refraction to where they are stored.
#include "render/photons/photon_pass.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <random>
#include <thread>

#include <glm/geometric.hpp>

#include "base/diagnostics.hpp"
#include "base/stop_request.hpp"
#include "render/frame.hpp"
#include "render/media.hpp"
#include "render/node.hpp"
#include "scene/object_extents.hpp"
#include "render/normal_frame.hpp"
#include "render/photons/photon_file.hpp"
#include "render/photons/photon_flags.hpp"
#include "render/shading.hpp"
#include "render/shadows.hpp"
#include "render/texture_layers.hpp"

namespace lumen::render {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMinDepth = 1e-4;       // as eye rays
constexpr int kMaxSkippedSurfaces = 64;  // no_image and pass_through surfaces in a row
// More photons than this from one light at one target is refused (a spacing far too small
// for the scene would otherwise run out of memory).
constexpr double kMaxPhotonsPerTarget = 5e7;

double grey(const glm::dvec3& c) { return 0.297 * c.x + 0.589 * c.y + 0.114 * c.z; }
double max_of(const glm::dvec3& c) { return std::max({c.x, c.y, c.z}); }

// Rodrigues' rotation of v about unit axis a.
glm::dvec3 rotate_about(const glm::dvec3& v, const glm::dvec3& a, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(a, v) * s + a * glm::dot(a, v) * (1 - c);
}

struct Target {
    const scene::Object* object;
    const scene::ObjectPhotons* flags;  // the object's own block (it is a target)
    Aabb box;
};

// The photon targets: objects whose photons block says target, found inside CSG that is not
// one itself; a target union (unless split_union off) is shot member by member, each with
// the union's flags (measured: POV-Ray's shot count is the sum of its members').
void find_targets(const scene::Object& o, const scene::Transform& parent, int depth,
                  const scene::ObjectPhotons* inherited, std::vector<Target>& out) {
    const scene::ObjectPhotons* flags =
        inherited ? inherited : o.photons && o.photons->target ? &*o.photons : nullptr;
    const auto* csg = std::get_if<scene::Csg>(&o.shape);
    const bool split = flags && csg && csg->op == scene::CsgOp::Union && o.split_union;
    if (flags && !split) {
        // POV-Ray aims at the object's own bounding box (min_extent / max_extent).
        const scene::Extents e = scene::object_extents(o);
        const Aabb box = transformed(Aabb{e.min, e.max}, parent);
        if (!box.empty() && box.finite()) out.push_back({&o, flags, box});
        return;
    }
    if (!csg || depth > kMaxNesting) return;
    const scene::Transform world = o.transform.then(parent);
    for (const auto& child : csg->children)
        if (child) find_targets(*child, world, depth + 1, split ? flags : nullptr, out);
}

// One light shooting at one target: the rings' geometry (POV's computeAnglesAndDeltas).
struct Combo {
    const LightSource* light;
    const Target* target;
    bool parallel;
    glm::dvec3 centre, axis, left;  // axis: towards the target's centre (or the light's direction)
    double radius, distance;        // bounding sphere radius; light to centre
    double spread, d_theta, theta_max;
    int copies = 1;                 // photons{area_light}: one per grid point
    InteriorList start;             // the interiors around where photons start
};

bool shoots(const LightSource& l, const scene::ObjectPhotons& t) {
    const scene::LightPhotons& lp = l.light->photons;
    return photon_follows(t.refraction, lp.refraction) || photon_follows(t.reflection, lp.reflection);
}

// POV-Ray's estimate of the spacing that shoots about `count` photons.
double spacing_for_count(const std::vector<Combo>& combos, int count) {
    double total = 0;
    for (const Combo& c : combos) {
        const scene::ObjectPhotons& t = *c.target->flags;
        const scene::LightPhotons& lp = c.light->light->photons;
        const bool refract = photon_follows(t.refraction, lp.refraction);
        const bool reflect = photon_follows(t.reflection, lp.reflection);
        double x = kPi * std::pow(c.radius / t.target_mult, 2);
        if (refract && reflect) x *= 1.5;
        if (t.collect) x *= refract && reflect ? 3 : 2;
        total += 0.5 * x;
    }
    return std::sqrt(total / count);
}

void set_rings(Combo& c, double spacing) {
    const double mult = c.target->flags->target_mult;
    double spread = mult * spacing;
    if (!c.parallel) spread /= c.distance;
    if (c.copies > 1) spread *= std::sqrt(double(c.copies));
    c.spread = spread;
    if (c.parallel) {
        c.d_theta = spread;
        c.theta_max = c.radius;
    } else {
        c.d_theta = std::atan(spread);
        c.theta_max = c.distance < c.radius ? kPi : std::asin(c.radius / c.distance);
    }
}

// The photons one ring left, whether any reached the target, and how many were shot.
struct RingResult {
    std::vector<Photon> photons, media_photons;
    uint64_t shot = 0;
    bool hit = false;
};

class PhotonTracer {
public:
    PhotonTracer(const Geometry& geometry, const Combo& combo, const scene::PhotonSettings& settings,
                 int max_level, double adc, std::mt19937_64& rng, RingResult& out)
        : geometry_(geometry), combo_(combo), light_(*combo.light),
          flags_(combo.light->light->photons), settings_(settings), max_level_(max_level),
          adc_(adc), rng_(&rng), out_(out.photons), media_out_(out.media_photons) {}

    // Traces a photon from the light; true when its first hit (past pass_through objects) is
    // the target. Each surface met is a level, pass_through ones included.
    bool trace(Ray ray, glm::dvec3 colour, double weight, int level, double travelled,
               InteriorList interiors) const {
        bool passed = false;  // the last surface met was passed through
        for (int i = 0; i < kMaxSkippedSurfaces; ++i, ++level) {
            if (level > max_level_ || weight < adc_) return false;
            Hit hit;
            if (!find_hit(ray, hit)) return false;
            if (level > 1 && !passed && settings_.media_steps > 0)
                colour = through_media(ray, hit.t, travelled, colour, interiors);
            travelled += hit.t;
            if (hit.interior && interiors.find(hit.interior_id) >= 0)
                colour *= interior_fade(*hit.interior, hit.t, true);
            // Only on the way to the target is a pass_through object passed through; after it,
            // the object is met as any other (POV-Ray).
            const bool before_target = level == 1 || passed;
            const bool pass = before_target && hit.photons && hit.photons->pass_through;
            if (before_target && !pass && hit.photon_target != combo_.target->object) return false;
            if (pass) {
                // Straight on, filtered by the surface.
                const SurfacePoint uv_only{hit.point, hit.normal, ray.dir, hit.uv};
                const glm::dvec3 f = surface_filter(facing_texture(hit, ray.dir), hit.point, &uv_only);
                colour *= f;
                weight *= std::max(max_of(f), 0.0);
                interiors.toggle(hit.interior_id, hit.interior, hit.hollow);
                ray.origin = hit.point;
                passed = true;
                continue;
            }
            if (level > 1 && !passed && collects_photons(hit.photons))
                deposit(hit.point, colour, travelled, -ray.dir);
            interact(ray, hit, colour, weight, level, travelled, interiors);
            return true;
        }
        return false;
    }

private:
    bool find_hit(const Ray& ray, Hit& hit) const {
        double t_min = kMinDepth;
        for (int i = 0; i < kMaxSkippedSurfaces; ++i) {
            // Photons see neither no_shadow (the query skips them) nor no_image objects.
            if (!geometry_.intersect(ray, t_min, std::numeric_limits<double>::infinity(), hit,
                                     Query::Shadow))
                return false;
            if (!hit.no_image) return true;
            t_min = hit.t;
        }
        return false;
    }

    // POV-Ray's media photons: along a segment through scattering media (each of its lead
    // media's intervals), photons about as far apart as neighbouring photon paths are there
    // (times the media factor, at most `media` of them per interval), each carrying the light
    // that entered the segment over its share of the path, undimmed; the photon leaves the
    // segment dimmed by the media's extinction.
    glm::dvec3 through_media(const Ray& ray, double length, double travelled,
                             const glm::dvec3& colour, const InteriorList& interiors) const {
        if (interiors.in_solid()) return colour;  // POV-Ray: no media inside a solid object
        thread_local std::vector<const scene::Media*> media;
        media_in(interiors, media);
        if (media.empty()) return colour;
        bool scatters = false;
        for (const scene::Media* m : media)
            scatters = scatters || (m->collect && m->scattering != glm::dvec3(0));
        const int intervals = std::clamp(lead_media(media).intervals, 1, 1000);
        const double ds = length / intervals;
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        // Path length from the light (1 for parallel light, whose spread is a length).
        const auto path = [&](double s) { return combo_.parallel ? 1.0 : travelled + s; };
        for (int i = 0; scatters && i < intervals; ++i) {
            const double s0 = i * ds;
            double factor = settings_.media_factor;
            const double step = combo_.spread * path(s0) * factor;
            if (!(step > 0) || !(ds > 0)) break;
            double n = std::floor(ds / step);
            if (n > settings_.media_steps) {
                n = settings_.media_steps;
                factor = ds / (combo_.spread * path(s0) * n);
            }
            for (int j = 0; j < int(n); ++j) {
                const double f = (j + 0.5 + settings_.jitter * (uniform(*rng_) - 0.5)) / n;
                const double s = s0 + f * ds, g = path(s);
                const double flux = factor * combo_.spread * g * combo_.spread * combo_.spread *
                                    g * g * light_fade(light_, travelled + s);
                media_out_.push_back(make_photon(ray.origin + s * ray.dir, colour * flux, -ray.dir));
            }
        }
        return colour * media_transmittance(media, ray, length);
    }

    void deposit(const glm::dvec3& p, const glm::dvec3& colour, double travelled,
                 const glm::dvec3& towards_origin) const {
        double scale = combo_.spread * combo_.spread * light_fade(light_, travelled);
        if (!combo_.parallel) scale *= travelled * travelled;
        out_.push_back(make_photon(p, colour * scale, towards_origin));
    }

    // Refraction through the surface and reflection per texture layer, as POV-Ray 3.7 traces
    // photons (refraction first, no Fresnel loss on the refracted photon). A photon carries a
    // weight, 1 from the light, and is dropped where its weight is below adc_bailout (probed
    // with POV-Ray's stored counts: one refraction through filter f keeps f of the weight, one
    // reflection of 0.1 keeps 0.01 of it). A layer's weight is the photon's times the layer's
    // share of what came through the layers above; its reflection keeps that times the
    // finish's reflection weight times the reflectivity's brightest channel, and carries the
    // photon's colour times the reflectivity. The refracted photon keeps the weight times the
    // filter's brightest channel. Total internal reflection takes the place of the reflections
    // made with the top normal and keeps the unfiltered colour.
    void interact(const Ray& ray, const Hit& hit, const glm::dvec3& colour, double weight,
                  int level, double travelled, const InteriorList& interiors) const {
        const glm::dvec3 d = ray.dir;
        glm::dvec3 raw_n = hit.normal;
        if (glm::dot(raw_n, d) > 0) raw_n = -raw_n;
        const scene::ObjectPhotons defaults;
        const scene::ObjectPhotons& own = hit.photons ? *hit.photons : defaults;
        const bool reflect = photon_follows(own.reflection, flags_.reflection);
        const bool refract = photon_follows(own.refraction, flags_.refraction);
        if (!reflect && !refract) return;
        ResolvedLayers layers;
        const SurfacePoint surface{hit.point, raw_n, d, hit.uv};
        resolve_layers(facing_texture(hit, d), hit.point, layers, &surface);
        InteriorList beyond;
        const double eta = cross_interface(interiors, hit.interior_id, hit.interior, hit.hollow, beyond);
        const double fresnel_ior = fresnel_relative_ior(interiors, hit.interior_id, eta);

        struct Reflection {
            glm::dvec3 normal, colour;
            double weight;
        };
        Reflection reflections[ResolvedLayers::kMax];
        int n_reflections = 0;
        glm::dvec3 filter(1), top_normal = raw_n;
        double through = 1;  // grey of what the layers so far let through, at most 1
        for (int i = 0; i < layers.count() && through > adc_; ++i) {
            const ResolvedLayer& layer = layers[i];
            const glm::dvec3 n = layer.normal ? framed_normal(*layer.normal, raw_n, layer.point,
                                                              layer.frame)
                                              : raw_n;
            if (i == 0) top_normal = n;
            const scene::Colour& c = layer.colour;
            const Reflectivity r =
                reflectivity(*layer.finish, -glm::dot(d, n), fresnel_ior, glm::dvec3(c.r, c.g, c.b));
            if (reflect && r.any()) {
                const double e = layer.finish->reflection_exponent;
                glm::dvec3 reflected = colour;
                if (e != 1 && e != 0)
                    reflected = glm::pow(glm::max(colour, glm::dvec3(0)), glm::dvec3(1 / e));
                reflections[n_reflections++] = {n, reflected * r.colour,
                                                weight * through * r.weight * max_of(r.colour)};
            }
            filter *= layer_filter(c);
            if (layer.finish->conserve_energy)
                filter *= glm::min(glm::dvec3(1), glm::dvec3(1) - r.colour);
            through = std::min(1.0, std::fabs(grey(filter)));
        }
        bool total_internal = false;
        if (refract && through > adc_) {
            const double w = weight * std::max(max_of(filter), 0.0);
            if (eta == 1.0) {
                trace(Ray{hit.point, d}, colour * filter, w, level + 1, travelled, beyond);
            } else {
                double cos_i = glm::dot(d, top_normal);
                const glm::dvec3 ln = cos_i <= 0 ? top_normal : -top_normal;
                cos_i = std::fabs(cos_i);
                const double k = 1 + eta * eta * (cos_i * cos_i - 1);
                total_internal = k < 0;
                if (total_internal) {
                    trace(Ray{hit.point, reflect_direction(d, top_normal, raw_n)}, colour, w,
                          level + 1, travelled, interiors);
                } else {
                    const glm::dvec3 dir = glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * ln);
                    trace(Ray{hit.point, dir}, colour * filter, w, level + 1, travelled, beyond);
                }
            }
        }
        if (!reflect) return;
        for (int i = 0; i < n_reflections; ++i) {
            const Reflection& r = reflections[i];
            if (total_internal && r.normal == top_normal) continue;
            trace(Ray{hit.point, reflect_direction(d, r.normal, raw_n)}, r.colour, r.weight,
                  level + 1, travelled, interiors);
        }
    }

    const Geometry& geometry_;
    const Combo& combo_;
    const LightSource& light_;
    const scene::LightPhotons& flags_;
    const scene::PhotonSettings& settings_;
    int max_level_;
    double adc_;
    std::mt19937_64* rng_;  // the ring's: media photon jitter
    std::vector<Photon>& out_;
    std::vector<Photon>& media_out_;
};

uint64_t ring_seed(size_t combo, size_t ring) {
    uint64_t h = (uint64_t(combo) << 32) ^ uint64_t(ring) ^ 0x9e3779b97f4a7c15ULL;
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
    return h;
}

// One ring of photons at angle theta from the axis (POV-Ray's loop over phi).
void shoot_ring(const Geometry& geometry, const Combo& c, size_t combo_index, size_t ring,
                double theta, const scene::PhotonSettings& settings, int max_level, double adc,
                RingResult& out) {
    std::mt19937_64 rng(ring_seed(combo_index, ring));
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const LightSource& l = *c.light;
    const double jitter = settings.jitter;
    const PhotonTracer tracer(geometry, c, settings, max_level, adc, rng, out);
    const double d_theta = c.d_theta;
    const double d_phi = theta < 1e-10 ? 2 * kPi : c.parallel ? d_theta / theta : d_theta / std::sin(theta);
    const double phi_min = -kPi + d_phi * uniform(rng) * 0.5;
    const double phi_max = kPi - d_phi / 2 + (phi_min + kPi);
    for (double phi = phi_min; phi < phi_max; phi += d_phi) {
        const double pj = phi + d_phi * (uniform(rng) - 0.5) * jitter;
        const double tj = theta + d_theta * (uniform(rng) - 0.5) * jitter;
        glm::dvec3 dir, origin;
        if (c.parallel) {
            dir = c.axis;
            origin = c.centre - glm::dot(c.centre - l.position, dir) * dir +
                     rotate_about(c.left * tj, dir, pj);
        } else {
            dir = glm::normalize(rotate_about(-std::sin(tj) * c.left + std::cos(tj) * c.axis, c.axis, pj));
            origin = l.position;
        }
        const double beam = beam_factor(l, origin + dir);
        if (beam < 1e-5) {  // outside a spotlight's cone: counted as shot, as POV-Ray counts
            out.shot += c.copies;
            continue;
        }
        const glm::dvec3 colour = l.colour * beam / double(c.copies);
        // Copies from an area light's grid: only the middle one's hit counts for autostop
        // (measured: POV-Ray's shot counts then match).
        const int middle = (l.n2 / 2) * l.n1 + l.n1 / 2;
        for (int k = 0; k < c.copies; ++k) {
            glm::dvec3 from = origin, towards = dir;
            if (c.copies > 1) {
                // From each grid point towards where the centre's photon crosses the target's
                // distance.
                from = area_sample_position(l, k % l.n1, k / l.n1, -dir);
                towards = glm::normalize(origin + dir * c.distance - from);
            }
            ++out.shot;
            const bool hit = tracer.trace(Ray{from, towards}, colour, 1.0, 1, 0.0, c.start);
            if (hit && (c.copies == 1 || k == middle)) out.hit = true;
        }
    }
}

// How the tracer gathers from a built map: the block's gather settings and start radius.
void set_gather(PhotonPass& pass, const scene::PhotonSettings& settings) {
    pass.gather.min = settings.gather_min;
    pass.gather.max = settings.gather_max;
    pass.gather.expand_percent = settings.expand_percent;
    pass.gather.expand_min = settings.expand_min;
    pass.gather.radius = settings.radius > 0 ? settings.radius * settings.radius_mult
                                             : pass.surface.choose_radius(settings.gather_max,
                                                                          settings.radius_mult);
    pass.media_gather = pass.gather;
    pass.media_gather.radius =
        settings.media_radius > 0
            ? settings.media_radius * settings.media_radius_mult
            : pass.media.choose_radius(settings.gather_max, settings.media_radius_mult, true);
}

}  // namespace

std::unique_ptr<PhotonPass> shoot_photons(const RenderFrame& frame, int threads) {
    const scene::Scene& scene = frame.scene();
    if (!scene.globals.photons) return nullptr;
    const scene::PhotonSettings& settings = *scene.globals.photons;
    if (settings.gather_max <= 0) return nullptr;
    auto pass = std::make_unique<PhotonPass>();
    if (!settings.load_file.empty()) {
        load_photons(*pass, settings.load_file, settings.file_loc);
        set_gather(*pass, settings);
        return pass;
    }
    const Geometry& geometry = frame.geometry();

    std::vector<Target> targets;
    for (const auto& o : scene.objects)
        if (o) find_targets(*o, scene::Transform{}, 0, nullptr, targets);
    std::vector<Combo> combos;
    for (const LightSource& l : frame.lights()) {
        if (l.shadowless || max_of(l.colour) <= 0) continue;  // fill lights shoot nothing
        if (l.group != 0) continue;  // a light_group's lights shoot no photons in lumen
        for (const Target& t : targets) {
            if (!shoots(l, *t.flags)) continue;
            Combo c{};
            c.light = &l;
            c.target = &t;
            c.parallel = l.parallel;
            c.centre = t.box.centre();
            c.radius = glm::length(c.centre - t.box.lo);
            c.distance = glm::length(c.centre - l.position);
            c.axis = c.parallel ? l.axis
                                : (c.distance > 0 ? (c.centre - l.position) / c.distance
                                                  : glm::dvec3(0, 0, 1));
            const glm::dvec3 up = std::fabs(std::fabs(c.axis.z) - 1) < 0.1 ? glm::dvec3(0, 1, 0)
                                                                            : glm::dvec3(0, 0, 1);
            c.left = glm::normalize(glm::cross(c.axis, up));
            if (l.area && l.light->photons.area_light && !c.parallel) c.copies = l.n1 * l.n2;
            c.start = geometry.interiors_around(c.parallel ? c.centre - glm::dot(c.centre - l.position, c.axis) * c.axis
                                                           : l.position);
            combos.push_back(c);
        }
    }
    pass->spacing = settings.count > 0 && !combos.empty() ? spacing_for_count(combos, settings.count)
                                                          : settings.spacing;
    // The rings of every light and target, shot in parallel and cut at autostop afterwards.
    struct Ring {
        size_t combo;
        double theta;
    };
    std::vector<Ring> rings;
    std::vector<size_t> first_ring;
    for (size_t i = 0; i < combos.size(); ++i) {
        Combo& c = combos[i];
        set_rings(c, pass->spacing);
        const double n = c.theta_max / c.d_theta;
        if (!(c.d_theta > 0) || !(n * n * kPi < kMaxPhotonsPerTarget))
            throw LumenError(settings.loc, "photons: the spacing " + std::to_string(pass->spacing) +
                                               " would shoot more than " +
                                               std::to_string(int64_t(kMaxPhotonsPerTarget)) +
                                               " photons at one target");
        first_ring.push_back(rings.size());
        for (double theta = 0; theta < c.theta_max; theta += c.d_theta) rings.push_back({i, theta});
    }
    first_ring.push_back(rings.size());
    const int max_level = settings.max_trace_level > 0 ? settings.max_trace_level
                                                       : std::clamp(scene.globals.max_trace_level, 1, 256);
    const double adc = settings.adc_bailout >= 0 ? settings.adc_bailout : scene.globals.adc_bailout;

    std::vector<RingResult> results(rings.size());
    std::atomic<size_t> next{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto worker = [&] {
        try {
            for (size_t i = next++; i < rings.size(); i = next++) {
                throw_if_stop_requested();
                const Ring& r = rings[i];
                shoot_ring(geometry, combos[r.combo], r.combo, i - first_ring[r.combo], r.theta,
                           settings, max_level, adc, results[i]);
            }
        } catch (...) {
            std::lock_guard lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            next = rings.size();
        }
    };
    unsigned n_threads = threads > 0 ? unsigned(threads) : std::max(1u, std::thread::hardware_concurrency());
    n_threads = std::max(1u, std::min<unsigned>(n_threads, unsigned(rings.size())));
    if (n_threads <= 1) {
        worker();
    } else {
        std::vector<std::thread> pool;
        for (unsigned i = 0; i < n_threads; ++i) pool.emplace_back(worker);
        for (auto& t : pool) t.join();
    }
    if (failure) std::rethrow_exception(failure);

    // Autostop: a ring that misses the target, past autostop·θmax, after one that hit it, ends
    // the shooting at that target.
    for (size_t i = 0; i < combos.size(); ++i) {
        bool hit_before = false;
        for (size_t k = first_ring[i]; k < first_ring[i + 1]; ++k) {
            RingResult& r = results[k];
            pass->shot += r.shot;
            pass->surface.append(r.photons);
            pass->media.append(r.media_photons);
            if (hit_before && !r.hit && rings[k].theta > settings.autostop * combos[i].theta_max)
                break;
            hit_before = hit_before || r.hit;
        }
    }
    results.clear();
    pass->surface.build();
    pass->media.build();
    set_gather(*pass, settings);
    if (!settings.save_file.empty()) save_photons(*pass, settings.save_file, settings.file_loc);
    return pass;
}

}  // namespace lumen::render

#include "render/shading.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "render/fog.hpp"
#include "render/media.hpp"
#include "render/shadows.hpp"
#include "render/texture_layers.hpp"

namespace lumen::render {
namespace {

constexpr double kEpsilon = 1e-10;

bool is_black(const glm::dvec3& c) {
    return std::fabs(c.x) < kEpsilon && std::fabs(c.y) < kEpsilon && std::fabs(c.z) < kEpsilon;
}

double max_component(const glm::dvec3& c) { return std::max({c.x, c.y, c.z}); }

// Where photons light the point, the light's photon flags: refracting targets shadow it black.
const scene::LightPhotons* photon_shadows(const LightSource& l, const SurfaceSample& s,
                                          const LightingEnv& env) {
    return env.photon_map && s.collects_photons && l.light ? &l.light->photons : nullptr;
}

// Sum of the recursive 4-corner averages over an area light's grid.
class AreaShadow {
public:
    AreaShadow(const LightSource& l, const SurfaceSample& s, const LightSample& centre,
               const LightingEnv& env, const InteriorList& interiors, ThreadState& state,
               Occluder* occluder)
        : l_(l), s_(s), centre_(centre), axes_(area_axes(l, centre.dir)), env_(env),
          interiors_(interiors), state_(state), occluder_(occluder) {
        const size_t n = size_t(l.n1) * l.n2;
        state.area_filter.resize(n);
        state.area_valid.assign(n, 0);
    }

    glm::dvec3 filter() { return block(0, 0, l_.n1 - 1, l_.n2 - 1, 0); }

private:
    glm::dvec3 sample(int u, int v) {
        const size_t k = size_t(v) * l_.n1 + u;
        if (!state_.area_valid[k]) {
            double ju = u, jv = v;
            if (l_.jitter) {
                ju += state_.uniform() - 0.5;
                jv += state_.uniform() - 0.5;
            }
            const glm::dvec3 pos = area_sample_position(l_, axes_, ju, jv);
            glm::dvec3 to = pos - s_.point;
            double dist = glm::length(to);
            if (l_.parallel) {
                to = centre_.dir;
                dist = glm::dot(pos - s_.point, to);
            } else if (dist > 0) {
                to /= dist;
            }
            const std::optional<double> reach = projection_reach(l_, s_.point, to, dist);
            state_.area_filter[k] =
                reach ? shadow_filter(*env_.geometry, s_.point, to, *reach, interiors_,
                                      state_.counters, nullptr, photon_shadows(l_, s_, env_),
                                      occluder_)
                      : glm::dvec3(0);
            state_.area_valid[k] = 1;
        }
        return state_.area_filter[k];
    }

    static double diff(const glm::dvec3& a, const glm::dvec3& b) {
        return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z);
    }

    glm::dvec3 block(int u1, int v1, int u2, int v2, int level) {
        const glm::dvec3 c00 = sample(u1, v1), c10 = sample(u2, v1);
        const glm::dvec3 c01 = sample(u1, v2), c11 = sample(u2, v2);
        const bool large = u2 - u1 > 1 || v2 - v1 > 1;
        // The corners are compared only where that decides (most blocks are single cells).
        auto differs = [&] {
            return diff(c00, c10) > 0.1 || diff(c10, c11) > 0.1 || diff(c11, c01) > 0.1 ||
                   diff(c01, c00) > 0.1;
        };
        if (large && (level < l_.adaptive || differs())) {
            const int ua = (u1 + u2) / 2, ub = (u1 + u2 + 1) / 2;  // floor and ceil of the middle
            const int va = (v1 + v2) / 2, vb = (v1 + v2 + 1) / 2;
            return 0.25 * (block(u1, v1, ua, va, level + 1) + block(ub, v1, u2, va, level + 1) +
                           block(u1, vb, ua, v2, level + 1) + block(ub, vb, u2, v2, level + 1));
        }
        return 0.25 * (c00 + c10 + c01 + c11);
    }

    const LightSource& l_;
    const SurfaceSample& s_;
    const LightSample& centre_;
    const AreaAxes axes_;
    const LightingEnv& env_;
    const InteriorList& interiors_;
    ThreadState& state_;
    Occluder* occluder_;
};

// Whether fog dims this light on its way to a surface: POV's `media_attenuation on`.
bool fog_dims(const LightSource& l, const LightingEnv& env) {
    return l.light && l.light->media_attenuation && l.light->media_interaction && env.fogs &&
           !env.fogs->empty();
}

// A perturbed normal can face a light behind the surface, whose shadow ray then enters the
// shaded object itself. POV counts that object's own surface from 1e-4 on, where every other
// surface counts only beyond the shadow tolerance (measured on spheres of radius 0.3 to 14:
// chords from 1e-4 shadow, of 8.5e-5 do not; another object 2e-4 away does not). Not always:
// POV left a pixel with a chord of 1.9e-4 lit where its neighbours sent no shadow ray, as if
// only the object that last blocked the light were tested with the finer tolerance.
constexpr double kSelfShadowTolerance = 1e-4;

bool shadowed_by_itself(const SurfaceSample& s, const glm::dvec3& dir, const LightingEnv& env) {
    if (!s.object || glm::dot(s.raw_normal, dir) >= 0) return false;
    Hit hit;
    if (!env.geometry->intersect(Ray{s.point, dir}, kSelfShadowTolerance, kShadowTolerance, hit,
                                 Query::Shadow))
        return false;
    return hit.object == s.object && !may_pass_light(hit.texture);
}

// The shadow filter of one light at the sample point, with the fog on the way where it dims
// the light. projected_through blocks light even for shadowless lights (tested along the ray
// to the light's centre), as in POV.
glm::dvec3 shadow_for(const LightSource& l, const SurfaceSample& s, const LightSample& ls,
                      const LightingEnv& env, const InteriorList& interiors, ThreadState& state) {
    Occluder* occluder = state.occluder(size_t(&l - env.lights->data()));
    glm::dvec3 filter;
    const bool fog = fog_dims(l, env);
    // Atmospheric media dims it likewise (object media always do: render/shadows.cpp).
    const bool media = atmosphere_dims(l, env);
    double solid = 0;  // the way inside solid objects, where there is no fog
    if (l.shadowless) {
        filter = glm::dvec3(projection_reach(l, s.point, ls.dir, ls.distance).has_value());
    } else if (shadowed_by_itself(s, ls.dir, env)) {
        return glm::dvec3(0);
    } else if (l.area && env.quality >= 5) {
        filter = AreaShadow(l, s, ls, env, interiors, state, occluder).filter();
    } else {
        const std::optional<double> reach = projection_reach(l, s.point, ls.dir, ls.distance);
        if (!reach) return glm::dvec3(0);
        filter = shadow_filter(*env.geometry, s.point, ls.dir, *reach, interiors, state.counters,
                               fog || media ? &solid : nullptr, photon_shadows(l, s, env),
                               occluder);
    }
    if (media && solid < ls.distance && filter != glm::dvec3(0))
        filter *= media_transmittance(*env.atmosphere, Ray{s.point, ls.dir}, ls.distance - solid);
    if (fog && solid < ls.distance)
        filter *= fog_along(*env.fogs, Ray{s.point, ls.dir}, ls.distance - solid,
                            env.noise_generator).attenuation;
    return filter;
}

// Whether lights can add anything to the surface: a clear surface without highlights (a media
// container's, typically) sends no shadow rays, which would cost a walk through its media each,
// nor does a black one without highlights (a mirror's, typically, met again on every bounce):
// diffuse light is the pigment's colour times the light's. With crand they are still sent, as
// crand draws a number for each light that reaches the surface.
bool takes_light(const scene::Finish& f, double opacity, const glm::dvec3& colour) {
    const bool diffuse = (f.diffuse > 0 || f.diffuse_back > 0) &&
                         ((opacity > 0 && colour != glm::dvec3(0)) || f.crand > 0);
    return diffuse || f.phong > 0 || f.specular > 0;
}

// c^e for a highlight, 0 where it is below 1e-34: c^e <= exp(e (c - 1)) since log c <= c - 1,
// so the test is safe, and it skips the pow on most of a surface (a tight highlight's exponent
// is in the hundreds). Nothing that small can show in a pixel.
double highlight_power(double c, double e) {
    if (e * (c - 1) < -78) return 0;
    return std::pow(c, e);
}

glm::dvec3 highlights(const SurfaceSample& s, const scene::Finish& f, const glm::dvec3& ldir,
                      double cos_light) {
    glm::dvec3 out(0);
    auto add = [&](double k) {
        if (k > 0)
            out += f.metallic > 0 ? k * metallic_factor(f.metallic, cos_light, s.colour)
                                  : glm::dvec3(k);
    };
    if (f.phong > 0) {
        const glm::dvec3 rv = s.view - 2 * glm::dot(s.view, s.normal) * s.normal;
        const double c = glm::dot(rv, ldir);
        if (c > 0 && !(f.phong_size >= 60 && c <= 0.0008)) {
            add(f.phong * highlight_power(c, f.phong_size));
        }
    }
    if (f.specular > 0) {
        const glm::dvec3 h = (ldir - s.view) * 0.5;
        const double len = glm::length(h);
        const double c = len > 0 ? glm::dot(h, s.normal) / len : 0;
        if (c > 0) {
            add(f.specular * highlight_power(c, 1.0 / f.roughness));
        }
    }
    return out;
}

}  // namespace

glm::dvec3 metallic_factor(double metallic, double cos_angle, const glm::dvec3& rgb) {
    const double x = std::acos(std::clamp(cos_angle, -1.0, 1.0)) / (std::numbers::pi / 2);
    const double fm =
        std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
    return glm::dvec3(1) + metallic * (1 - fm) * (rgb - glm::dvec3(1));
}

glm::dvec3 irid_factor(const scene::Finish& f, double thickness, const glm::dvec3& wavelength,
                       double cos_light, double cos_view) {
    const double phase =
        2 * std::numbers::pi * thickness * (std::fabs(cos_light) + std::fabs(cos_view));
    glm::dvec3 out(1);
    for (int c = 0; c < 3; ++c)
        if (wavelength[c] > 0) out[c] += f.irid_amount * std::cos(phase / wavelength[c]);
    return out;
}

// Measured from povray 3.7 renders of a plane under a parallel light, by solving each pixel
// for the thickness: the turbulence is taken at the world point, unscaled.
double irid_thickness(const scene::Finish& f, const glm::dvec3& p, noise::Generator generator) {
    if (f.irid_turbulence == 0) return f.irid_thickness;
    scene::TurbulenceParams params;
    params.octaves = 5;
    const double t = noise::turbulence(p, params, generator);
    return f.irid_thickness * (1 + f.irid_turbulence * (2 * t - 1));
}

glm::dvec3 local_light(const SurfaceSample& s, const LightingEnv& env,
                       const InteriorList& interiors, ThreadState& state) {
    const scene::Finish& f = *s.finish;
    if (env.quality <= 1) return s.colour;  // quick colour: the pigment at full ambient
    glm::dvec3 out(0);
    if (!env.ambient_off) out += s.colour * f.ambient * env.ambient_light * s.opacity;
    out += s.colour * f.emission * s.opacity;
    if (!env.lights || !takes_light(f, s.opacity, s.colour)) return out;
    for (const LightSource& l : *env.lights) {
        LightSample ls;
        if (!lights_surface(l, s.light_group, s.global_lights) || !illuminate(l, s.point, ls)) continue;
        const double cos_light = glm::dot(s.normal, ls.dir);
        bool backside = false;
        double intensity_cos = cos_light;
        if (cos_light < kEpsilon) {
            if (s.double_illuminate) {
                intensity_cos = std::fabs(cos_light);
            } else if (f.diffuse_back > 0) {
                backside = true;
                intensity_cos = std::fabs(cos_light);
            } else {
                continue;
            }
        }
        glm::dvec3 lc = ls.colour;
        if (env.quality >= 4) {
            lc *= shadow_for(l, s, ls, env, interiors, state);
            if (is_black(lc)) continue;
        }
        if (f.irid_amount > 0)
            lc *= irid_factor(f, s.film_thickness, env.irid_wavelength, cos_light,
                              glm::dot(s.normal, s.view));
        const double diffuse = backside ? f.diffuse_back : f.diffuse;
        if (diffuse > 0) {
            double k = f.brilliance == 1 ? intensity_cos : std::pow(intensity_cos, f.brilliance);
            k = k * diffuse * s.opacity;
            if (f.crand > 0) k -= f.crand * state.uniform();
            out += k * s.colour * lc;
        }
        if (!l.shadowless && !backside && cos_light >= kEpsilon)
            out += highlights(s, f, ls.dir, cos_light) * lc;
    }
    return out;
}

glm::dvec3 photon_light(const SurfaceSample& s, const GatheredPhotons& photons) {
    if (photons.count() == 0 || !(photons.radius_sq > 0)) return glm::dvec3(0);
    const scene::Finish& f = *s.finish;
    glm::dvec3 sum(0);
    for (const Photon* p : photons.photons) {
        const glm::dvec3 dir = p->direction();
        // Lambert compensation: the estimate divides by the cosine it will multiply by.
        const glm::dvec3 flux = p->colour() / std::clamp(glm::dot(s.raw_normal, dir), 0.1, 1.0);
        const double cos_light = glm::dot(s.normal, dir);
        double intensity_cos = cos_light;
        double diffuse = f.diffuse;
        const bool front = cos_light >= kEpsilon;
        if (!front) {
            if (s.double_illuminate) intensity_cos = std::fabs(cos_light);
            else if (f.diffuse_back > 0) intensity_cos = std::fabs(cos_light), diffuse = f.diffuse_back;
            else continue;
        }
        if (diffuse > 0) {
            const double k = f.brilliance == 1 ? intensity_cos : std::pow(intensity_cos, f.brilliance);
            sum += k * diffuse * s.opacity * s.colour * flux;
        }
        if (front) sum += highlights(s, f, dir, cos_light) * flux;
    }
    return sum / (std::numbers::pi * photons.radius_sq);
}

Reflectivity reflectivity(const scene::Finish& f, double cos_i, double relative_ior,
                          const glm::dvec3& pigment) {
    Reflectivity r;
    const glm::dvec3 rmin = f.reflection_min, rmax = f.reflection_max;
    if (is_black(rmin) && is_black(rmax)) return r;
    if (f.fresnel) {
        const double n = relative_ior, c = cos_i;
        const double g2 = n * n + c * c - 1;
        if (g2 <= 0) {
            r.colour = rmax;
        } else {
            const double g = std::sqrt(g2);
            const double a = (g - c) / (g + c);
            const double b = (c * (g + c) - 1) / (c * (g - c) + 1);
            const double fr = std::clamp(0.5 * a * a * (1 + b * b), 0.0, 1.0);
            r.colour = fr * rmax + (1 - fr) * rmin;
        }
        r.weight = max_component(r.colour);
    } else {
        const double frac =
            f.reflection_falloff == 1 ? 1 - cos_i : std::pow(1 - cos_i, f.reflection_falloff);
        if (std::fabs(frac) < kEpsilon)
            r.colour = rmin;
        else if (std::fabs(frac - 1) < kEpsilon)
            r.colour = rmax;
        else
            r.colour = frac * rmax + (1 - frac) * rmin;
        r.weight = std::max(max_component(rmax), max_component(rmin));
    }
    if (f.reflection_metallic > 0)
        r.colour *= metallic_factor(f.reflection_metallic, cos_i, pigment);
    return r;
}

glm::dvec3 reflect_direction(const glm::dvec3& d, const glm::dvec3& nl, const glm::dvec3& n) {
    glm::dvec3 r = d - 2 * glm::dot(d, nl) * nl;
    const double rn = glm::dot(r, n);
    if (rn < 0) {
        // Perturbed normals can send the ray below the real surface: bend it back.
        if (glm::dot(r, nl) < 0)
            r = d - 2 * glm::dot(d, n) * n;
        else
            r -= 2 * rn * n;
    }
    return glm::normalize(r);
}

}  // namespace lumen::render

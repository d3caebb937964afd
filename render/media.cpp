#include "render/media.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "render/lights.hpp"
#include "render/pigment.hpp"
#include "render/shadows.hpp"

namespace lumen::render {
namespace {

constexpr int kMaxLitLights = 32;  // lights past this many scatter nothing (ranges kept per light)
constexpr int kMaxIntervals = 1000;
constexpr int kMaxPieces = 2 * kMaxLitLights + 1;  // lit ranges with the unlit gaps between them

struct Range {
    double start = 0, end = 0;
};

// The part of the ray inside a spotlight's falloff cone or a cylinder light's falloff radius:
// the quadratic's roots cut the ray, and the pieces whose middle is lit make the range.
std::optional<Range> lit_range(const LightSource& l, const Ray& ray, double depth) {
    if (!l.spot && !l.cylinder) return Range{0, depth};
    const glm::dvec3 v = ray.origin - l.position, d = ray.dir, a = l.axis;
    const double da = glm::dot(d, a), va = glm::dot(v, a);
    double qa, qb, qc;
    if (l.spot) {
        const double c2 = l.cos_falloff * l.cos_falloff;
        qa = da * da - c2 * glm::dot(d, d);
        qb = 2 * (da * va - c2 * glm::dot(d, v));
        qc = va * va - c2 * glm::dot(v, v);
    } else {
        const glm::dvec3 dp = d - da * a, vp = v - va * a;
        qa = glm::dot(dp, dp);
        qb = 2 * glm::dot(dp, vp);
        qc = glm::dot(vp, vp) - l.falloff * l.falloff;
    }
    auto inside = [&](double t) {
        const glm::dvec3 p = v + t * d;
        const double along = glm::dot(p, a);
        if (along <= 0) return false;
        if (l.spot) return along * along >= l.cos_falloff * l.cos_falloff * glm::dot(p, p);
        return glm::dot(p, p) - along * along <= l.falloff * l.falloff;
    };
    constexpr double kFar = 1e7;  // an unbounded range ends here
    double cuts[4] = {0, kFar, kFar, kFar};
    int n = 1;
    if (std::fabs(qa) > 1e-12) {
        const double disc = qb * qb - 4 * qa * qc;
        if (disc >= 0) {
            const double s = std::sqrt(disc);
            cuts[n++] = std::clamp((-qb - s) / (2 * qa), 0.0, kFar);
            cuts[n++] = std::clamp((-qb + s) / (2 * qa), 0.0, kFar);
        }
    } else if (std::fabs(qb) > 1e-12) {
        cuts[n++] = std::clamp(-qc / qb, 0.0, kFar);
    }
    cuts[n++] = kFar;
    std::sort(cuts, cuts + n);
    std::optional<Range> out;
    for (int i = 0; i + 1 < n; ++i) {
        if (cuts[i + 1] <= cuts[i] || !inside(0.5 * (cuts[i] + cuts[i + 1]))) continue;
        if (!out) out = Range{cuts[i], cuts[i + 1]};
        else out->end = cuts[i + 1];
    }
    if (!out || !(out->start < depth) || !(out->end > 0.001)) return std::nullopt;
    return Range{std::max(out->start, 0.0), std::min(out->end, depth)};
}

// One sample's coefficients: extinction, and the light emitted or scattered towards the eye.
struct Coefficients {
    glm::dvec3 extinction{0}, emitted{0};
};

class Integrator {
public:
    Integrator(const std::vector<const scene::Media*>& media, const Ray& ray, bool lit,
               const LightingEnv* env, const InteriorList* interiors, ThreadState* state,
               const scene::Media* lead = nullptr)
        : media_(media), ray_(ray), lit_(lit), env_(env), interiors_(interiors), state_(state) {
        // A segment of several media takes its sampling from the first with the most intervals
        // (unless told otherwise).
        lead_ = lead ? lead : &lead_media(media);
        threshold_ = lead_->aa_threshold;
        for (const scene::Media* m : media) {
            threshold_ = std::min(threshold_, m->aa_threshold);
            constant_ = constant_ && m->constant();
        }
    }

    MediaEffect run(double depth) {
        plan_intervals(depth);
        glm::dvec3 od(0), te(0);
        for (int i = 0; i < n_intervals_; ++i) {
            const double s0 = starts_[i], ds = starts_[i + 1] - starts_[i];
            if (!(ds > 0)) continue;
            glm::dvec3 ie(0), io(0);
            int n = 0;
            if (!lit_ && constant_) {  // shadow rays through constant media: Beer-Lambert
                io = coefficients(s0).extinction * ds;
                n = 1;
            } else if (lead_->method == 3) {
                adaptive(s0, ds, ie, io, n);
            } else {
                regular(s0, ds, ie, io, n);
            }
            te += (ie / double(n)) * glm::exp(-od);
            od += io / double(n);
        }
        return {te, glm::exp(-od)};
    }

private:
    // §2.3 of POV-Ray's media: pieces lit by some light get `ratio` of the intervals.
    void plan_intervals(double depth) {
        n_lights_ = 0;
        if (lit_ && env_ && env_->lights) {
            for (const LightSource& l : *env_->lights) {
                if (n_lights_ == kMaxLitLights) break;
                if (l.shadowless || (l.light && !l.light->media_interaction)) continue;
                // A light_group's lights scatter only in its members' media; lumen leaves
                // them out of media (no corpus scene puts media in a group).
                if (l.group != 0) continue;
                if (const auto r = lit_range(l, ray_, depth)) {
                    lights_[n_lights_] = &l;
                    ranges_[n_lights_++] = *r;
                }
            }
        }
        // The lit union as alternating pieces over [0, depth] (fixed arrays: no allocation
        // per ray).
        Range lit[kMaxLitLights];
        std::copy(ranges_, ranges_ + n_lights_, lit);
        std::sort(lit, lit + n_lights_, [](const Range& a, const Range& b) { return a.start < b.start; });
        struct Piece { double start, end; bool lit; };
        Piece pieces[kMaxPieces];
        int count = 0;
        double at = 0;
        for (int i = 0; i < n_lights_;) {
            Range u = lit[i++];
            while (i < n_lights_ && lit[i].start <= u.end) u.end = std::max(u.end, lit[i++].end);
            if (u.start > at) pieces[count++] = {at, u.start, false};
            pieces[count++] = {std::max(u.start, at), u.end, true};
            at = u.end;
        }
        if (at < depth || count == 0) pieces[count++] = {at, depth, false};
        const int wanted = std::min(std::max(lead_->intervals, count), kMaxIntervals);
        n_intervals_ = 0;
        auto cut = [&](const Piece& p, int n) {
            for (int k = 0; k < n; ++k) starts_[n_intervals_++] = p.start + (p.end - p.start) * k / n;
        };
        if (count == 1) {
            cut({0, depth, pieces[0].lit}, !pieces[0].lit && constant_ ? 1 : wanted);
        } else {
            double total = 0;
            for (int i = 0; i < count; ++i) total += pieces[i].lit ? lead_->ratio : 1 - lead_->ratio;
            int remaining = wanted;
            for (int i = 0; i < count; ++i) {
                const double w = pieces[i].lit ? lead_->ratio : 1 - lead_->ratio;
                int n = int(std::floor(total > 0 ? w / total * wanted : 0)) + 1;
                n = std::max(1, std::min(n, remaining - count + i + 1));
                remaining -= n;
                cut(pieces[i], n);
            }
        }
        starts_[n_intervals_] = depth;
    }

    Coefficients coefficients(double s) {
        const glm::dvec3 p = ray_.origin + s * ray_.dir;
        Coefficients c;
        glm::dvec3 scattering(0);
        for (const scene::Media* m : media_) {
            glm::dvec3 density(1);
            for (const auto& d : m->densities) {
                const scene::Colour dc = evaluate_pigment(d.get(), p, nullptr);
                density *= glm::dvec3(dc.r, dc.g, dc.b);
            }
            c.extinction += density * (m->absorption + m->extinction * m->scattering);
            if (!lit_) continue;
            c.emitted += density * m->emission;
            scattering += density * m->scattering;
        }
        if (!lit_ || scattering == glm::dvec3(0)) return c;
        if (env_->media_photons) c.emitted += scattering * photon_light(p);
        for (int i = 0; i < n_lights_; ++i) {
            if (s < ranges_[i].start || s > ranges_[i].end) continue;
            const LightSource& l = *lights_[i];
            LightSample ls;
            if (!illuminate(l, p, ls)) continue;
            const std::optional<double> reach = projection_reach(l, p, ls.dir, ls.distance);
            if (!reach) continue;
            // As on surfaces, a photon target that refracts this light shadows it black where
            // photons light the scene (POV-Ray: its photons take the place of the light).
            const scene::LightPhotons* refracted =
                env_->photon_map && l.light ? &l.light->photons : nullptr;
            glm::dvec3 filter = shadow_filter(*env_->geometry, p, ls.dir, *reach, *interiors_,
                                              state_->counters, nullptr, refracted);
            if (filter != glm::dvec3(0) && atmosphere_dims(l, *env_))
                filter *= media_transmittance(*env_->atmosphere, Ray{p, ls.dir}, ls.distance);
            if (filter == glm::dvec3(0)) continue;
            const double k = mean_phase(media_, glm::dot(ls.dir, ray_.dir));
            c.emitted += k * scattering * ls.colour * filter;
        }
        return c;
    }

    // The media photons around p, each scattered towards the eye by the media's mean phase
    // function, over the sphere that holds them (POV-Ray's volume estimate, before σ_s).
    glm::dvec3 photon_light(const glm::dvec3& p) const {
        thread_local GatheredPhotons gathered;
        env_->media_photons->gather_adaptive(p, glm::dvec3(0), env_->media_gather, gathered);
        if (gathered.count() == 0 || !(gathered.radius_sq > 0)) return glm::dvec3(0);
        glm::dvec3 sum(0);
        for (const Photon* ph : gathered.photons)
            sum += mean_phase(media_, glm::dot(ph->direction(), ray_.dir)) * ph->colour();
        const double r = std::sqrt(gathered.radius_sq);
        return sum * (3 / (4 * std::numbers::pi * r * r * r));
    }

    struct Sample {
        glm::dvec3 c, o;  // emitted and extinction, times the interval's length
    };
    Sample sample(double s0, double ds, double f) {
        const Coefficients c = coefficients(s0 + f * ds);
        return {c.emitted * ds, c.extinction * ds};
    }
    double uniform() { return state_ ? state_->uniform() : 0.5; }
    double jitter() { return lead_->jitter == 0 || !state_ ? 0 : lead_->jitter * (uniform() - 0.5); }

    static double distance(const glm::dvec3& a, const glm::dvec3& b) {
        const glm::dvec3 d = glm::abs(a - b);
        return d.x + d.y + d.z;
    }

    Sample refine(double s0, double ds, double a, double b, const Sample& sa, const Sample& sb,
                  int depth) {
        const double m = (a + b) / 2;
        const Sample sm = sample(s0, ds, m + (b - a) * jitter());
        if (depth <= 0) return {(sa.c + sm.c + sb.c) / 3.0, (sa.o + sm.o + sb.o) / 3.0};
        Sample left, right;
        if (distance(sa.c, sm.c) > threshold_) {
            const Sample r = refine(s0, ds, a, m, sa, sm, depth - 1);
            left = {r.c / 2.0, r.o / 2.0};
        } else {
            left = {sa.c / 3.0 + sm.c / 6.0, sa.o / 3.0 + sm.o / 6.0};
        }
        if (distance(sm.c, sb.c) > threshold_) {
            const Sample r = refine(s0, ds, m, b, sm, sb, depth - 1);
            right = {r.c / 2.0, r.o / 2.0};
        } else {
            right = {sm.c / 6.0 + sb.c / 3.0, sm.o / 6.0 + sb.o / 3.0};
        }
        return {left.c + right.c, left.o + right.o};
    }

    // Method 3: sc sub-steps 1/(sc + 1) apart (POV-Ray leaves the interval's last step out),
    // each refined to aa_level where the emission changes by more than aa_threshold.
    void adaptive(double s0, double ds, glm::dvec3& te, glm::dvec3& od, int& n) {
        const int sc = std::max(2, lead_->samples_min / 2 + 1);
        const double h = 1.0 / (sc + 1);
        Sample prev = sample(s0, ds, h * jitter());
        for (int j = 1; j <= sc; ++j) {
            const double f = j * h;
            const Sample next = sample(s0, ds, f + h * jitter());
            const Sample r = refine(s0, ds, f - h, f, prev, next, lead_->aa_level - 1);
            te += r.c * glm::exp(-od / double(sc));
            od += r.o;
            prev = next;
        }
        n = sc;
    }

    // Methods 1 and 2: samples_min samples, each attenuated by its own extinction up to it.
    void regular(double s0, double ds, glm::dvec3& te, glm::dvec3& od, int& n) {
        const int count = lead_->samples_min;
        for (int j = 0; j < count; ++j) {
            const double f = lead_->method == 2
                                 ? (j + 0.5) / count + uniform() * lead_->jitter / count
                                 : uniform();
            const Sample s = sample(s0, ds, f);
            od += s.o;
            te += s.c * glm::exp(-s.o * f);
        }
        n = count;
    }

    const std::vector<const scene::Media*>& media_;
    const Ray& ray_;
    bool lit_;
    const LightingEnv* env_;
    const InteriorList* interiors_;
    ThreadState* state_;
    const scene::Media* lead_ = nullptr;
    double threshold_ = 0.1;
    bool constant_ = true;
    const LightSource* lights_[kMaxLitLights] = {};
    Range ranges_[kMaxLitLights];
    int n_lights_ = 0;
    double starts_[kMaxIntervals + 1];  // the intervals' bounds, n_intervals_ + 1 of them
    int n_intervals_ = 0;
};

}  // namespace

void media_in(const InteriorList& interiors, std::vector<const scene::Media*>& out) {
    out.clear();
    for (int i = 0; i < interiors.size(); ++i)
        if (const scene::Interior* in = interiors[i].interior)
            for (const auto& m : in->media) out.push_back(m.get());
}

bool atmosphere_dims(const LightSource& l, const LightingEnv& env) {
    return l.light && l.light->media_attenuation && l.light->media_interaction && env.atmosphere &&
           !env.atmosphere->empty();
}

glm::dvec3 media_transmittance(const std::vector<const scene::Media*>& media, const Ray& ray,
                               double depth, const scene::Media* lead) {
    if (media.empty() || !(depth > 0)) return glm::dvec3(1);
    Integrator in(media, ray, false, nullptr, nullptr, nullptr, lead);
    const glm::dvec3 t = in.run(std::min(depth, kMediaEscapeDepth)).transmittance;
    return glm::dvec3(std::isfinite(t.x) ? t.x : 0, std::isfinite(t.y) ? t.y : 0,
                      std::isfinite(t.z) ? t.z : 0);
}

const scene::Media& lead_media(const std::vector<const scene::Media*>& media) {
    const scene::Media* lead = media.front();
    for (const scene::Media* m : media)
        if (m->intervals > lead->intervals) lead = m;
    return *lead;
}

double mean_phase(const std::vector<const scene::Media*>& media, double alpha) {
    double k = 0;
    for (const scene::Media* m : media) k += phase(*m, alpha);
    return k / double(media.size());
}

double phase(const scene::Media& m, double alpha) {
    switch (m.scattering_type) {
        case 2: return 0.576655375 * (1 + 9 * std::pow((1 + alpha) / 2, 8));
        case 3: return 0.495714547 * (1 + 50 * std::pow((1 + alpha) / 2, 32));
        case 4: return 0.799372013 * (1 + alpha * alpha);
        case 5: {
            const double g = m.eccentricity;
            return (1 - g * g) / std::pow(1 + g * g - 2 * g * alpha, 1.5);
        }
        default: return 1;
    }
}

MediaEffect integrate_media(const std::vector<const scene::Media*>& media, const Ray& ray,
                            double depth, bool lit, const LightingEnv& env,
                            const InteriorList& interiors, ThreadState& state) {
    if (media.empty() || !(depth > 0)) return {};
    Integrator in(media, ray, lit, &env, &interiors, &state);
    MediaEffect e = in.run(depth);
    // No NaN or infinity reaches a pixel: saturating media stay finite.
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(e.added[c])) e.added[c] = e.added[c] > 0 ? 1e30 : 0;
        if (!std::isfinite(e.transmittance[c])) e.transmittance[c] = 0;
    }
    return e;
}

}  // namespace lumen::render

// photons { } blocks as JSON, for the scene dump (interp/dump_scene.cpp).
#include "interp/dump_photons.hpp"

namespace lumen::interp::dump {

namespace {

const char* toggle_text(scene::PhotonToggle t) {
    return t == scene::PhotonToggle::On ? "on" : t == scene::PhotonToggle::Off ? "off" : "unset";
}

void put_toggle(Json& o, const char* key, scene::PhotonToggle t) {
    if (t != scene::PhotonToggle::Unset) o.put(key, Json::str(toggle_text(t)));
}

}  // namespace

Json object_photons(const scene::ObjectPhotons& p) {
    const scene::ObjectPhotons d;
    Json o;
    put_if(o, "target", p.target, d.target);
    put_if(o, "target_mult", p.target_mult, d.target_mult);
    put_toggle(o, "refraction", p.refraction);
    put_toggle(o, "reflection", p.reflection);
    put_if(o, "collect", p.collect, d.collect);
    put_if(o, "pass_through", p.pass_through, d.pass_through);
    return o;
}

Json global_photons(const scene::PhotonSettings& p) {
    const scene::PhotonSettings d;
    Json o;
    put_if(o, "spacing", p.spacing, d.spacing);
    put_if(o, "count", double(p.count), double(d.count));
    put_if(o, "gather_min", double(p.gather_min), double(d.gather_min));
    put_if(o, "gather_max", double(p.gather_max), double(d.gather_max));
    put_if(o, "media_steps", double(p.media_steps), double(d.media_steps));
    put_if(o, "media_factor", p.media_factor, d.media_factor);
    put_if(o, "jitter", p.jitter, d.jitter);
    put_if(o, "max_trace_level", double(p.max_trace_level), double(d.max_trace_level));
    put_if(o, "adc_bailout", p.adc_bailout, d.adc_bailout);
    put_if(o, "autostop", p.autostop, d.autostop);
    put_if(o, "expand_percent", p.expand_percent, d.expand_percent);
    put_if(o, "expand_min", double(p.expand_min), double(d.expand_min));
    put_if(o, "radius", p.radius, d.radius);
    put_if(o, "radius_mult", p.radius_mult, d.radius_mult);
    put_if(o, "media_radius", p.media_radius, d.media_radius);
    put_if(o, "media_radius_mult", p.media_radius_mult, d.media_radius_mult);
    return o;
}

Json light_photons(const scene::LightPhotons& p) {
    Json o;
    put_toggle(o, "refraction", p.refraction);
    put_toggle(o, "reflection", p.reflection);
    put_if(o, "area_light", p.area_light, false);
    return o;
}

}  // namespace lumen::interp::dump

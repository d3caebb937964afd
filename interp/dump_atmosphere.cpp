// fog and rainbow as JSON, for the scene dump (interp/dump_scene.cpp).
#include "interp/dump_atmosphere.hpp"

#include "interp/dump_pattern.hpp"

namespace lumen::interp::dump {

Json fog(const scene::Fog& f) {
    const scene::Fog d;
    Json o;
    put_if(o, "fog_type", double(f.type), double(d.type));
    put_if(o, "distance", f.distance, d.distance);
    put_if(o, "colour", f.colour, d.colour);
    put_if(o, "turbulence", f.turbulence.amount, d.turbulence.amount);
    put_if(o, "octaves", double(f.turbulence.octaves), double(d.turbulence.octaves));
    put_if(o, "omega", f.turbulence.omega, d.turbulence.omega);
    put_if(o, "lambda", f.turbulence.lambda, d.turbulence.lambda);
    put_if(o, "turb_depth", f.turb_depth, d.turb_depth);
    put_if(o, "offset", f.offset, d.offset);
    put_if(o, "alt", f.alt, d.alt);
    put_if(o, "up", f.up, d.up);
    put_transform(o, f.transform);
    if (f.unsupported) o.put("unsupported", unsupported_text(*f.unsupported));
    return o;
}

Json rainbow(const scene::Rainbow& r) {
    const scene::Rainbow d;
    Json o;
    put_if(o, "direction", r.direction, d.direction);
    put_if(o, "angle", r.angle, d.angle);
    put_if(o, "width", r.width, d.width);
    put_if(o, "distance", r.distance, d.distance);
    put_if(o, "jitter", r.jitter, d.jitter);
    put_if(o, "up", r.up, d.up);
    if (!r.colour_map.empty()) o.put("colour_map", colour_map(r.colour_map));
    if (r.arc) {
        o.put("arc_angle", Json::num(r.arc->arc_angle));
        o.put("falloff_angle", Json::num(r.arc->falloff_angle));
    }
    return o;
}

}  // namespace lumen::interp::dump

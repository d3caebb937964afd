// Test helpers for the tracer: scene::Scene values built in C++, a tiny sphere/plane
// intersector (independent of render::Geometry), rendering to 8-bit and reading the
// reference PPMs in render/testdata.
#pragma once
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "render/antialias.hpp"
#include "render/camera.hpp"
#include "render/image_output.hpp"
#include "render/intersector.hpp"
#include "render/tracer.hpp"

namespace lumen::render::test {

inline scene::Scene scene_37() {
    scene::Scene s;
    s.language_version = 3.7;
    s.version_given = true;
    s.globals.assumed_gamma = 1.0;
    return s;
}

// Camera fixed up like the interpreter does for `location` + `look_at` with default vectors.
inline scene::Camera look_at_camera(glm::dvec3 location, glm::dvec3 look_at) {
    scene::Camera c;
    c.location = location;
    const glm::dvec3 d = glm::normalize(look_at - location);
    const glm::dvec3 r = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), d));
    c.direction = d;
    c.right = r * 1.33;
    c.up = glm::cross(d, r);
    return c;
}

struct Material {
    Material() = default;
    Material(scene::Colour c) : colour(c) {}  // NOLINT: implicit on purpose, `Material m{c}`
    scene::Colour colour{0, 0, 0, 0, 0};
    scene::Finish finish;
    std::optional<scene::Interior> interior;
    scene::PigmentPtr pigment;  // overrides colour when set
};

inline scene::LayeredTexture texture_of(const Material& m) {
    auto pig = m.pigment;
    if (!pig) {
        auto p = std::make_shared<scene::Pigment>();
        p->colour = m.colour;
        pig = p;
    }
    auto t = std::make_shared<scene::Texture>();
    t->pigment = pig;
    t->finish = std::make_shared<scene::Finish>(m.finish);
    return {t};
}

inline scene::ObjectPtr sphere(glm::dvec3 c, double r, const Material& m) {
    auto o = std::make_shared<scene::Object>();
    o->shape = scene::Sphere{c, r};
    o->texture = texture_of(m);
    o->interior = m.interior;
    return o;
}

inline scene::ObjectPtr plane(glm::dvec3 n, double d, const Material& m) {
    auto o = std::make_shared<scene::Object>();
    o->shape = scene::Plane{glm::normalize(n), d};
    o->texture = texture_of(m);
    o->interior = m.interior;
    return o;
}

inline scene::PigmentPtr checker(scene::Colour a, scene::Colour b) {
    auto p = std::make_shared<scene::Pigment>();
    p->pattern.kind = scene::make_pattern_kind(scene::PatternType::Checker);
    p->colour_map = {{0, a}, {1, b}};
    p->list_form = true;
    return p;
}

inline scene::Colour rgb(double r, double g, double b) { return {r, g, b, 0, 0}; }

inline scene::Light point_light(glm::dvec3 pos, glm::dvec3 colour) {
    scene::Light l;
    l.position = pos;
    l.colour = colour;
    return l;
}

// Spheres and planes of a scene, untransformed.
class TestIntersector final : public Intersector {
public:
    explicit TestIntersector(const scene::Scene& s) : scene_(s) {}
    bool intersect(const Ray& ray, double t_min, double t_max, Hit& hit,
                   Query query) const override {
        bool found = false;
        for (const scene::ObjectPtr& o : scene_.objects) {
            if (query != Query::All && o->no_shadow) continue;
            double t = 0;
            glm::dvec3 n;
            if (!nearest(*o, ray, std::max(t_min, 1e-6), t_max, t, n)) continue;
            t_max = t;
            found = true;
            hit.t = t;
            hit.point = ray.at(t);
            hit.normal = n;
            hit.object = o.get();
            hit.texture = o->texture.empty() ? nullptr : &o->texture;
            hit.interior_texture = o->interior_texture.empty() ? nullptr : &o->interior_texture;
            hit.interior = o->interior ? &*o->interior : nullptr;
            hit.interior_id = o.get();
            hit.no_image = o->no_image;
            hit.no_reflection = o->no_reflection;
            hit.double_illuminate = o->double_illuminate;
        }
        return found;
    }

private:
    static bool nearest(const scene::Object& o, const Ray& ray, double t_min, double t_max,
                        double& t, glm::dvec3& n) {
        if (auto* s = std::get_if<scene::Sphere>(&o.shape)) {
            const glm::dvec3 oc = ray.origin - s->center;
            const double b = glm::dot(oc, ray.dir);
            const double c = glm::dot(oc, oc) - s->radius * s->radius;
            const double disc = b * b - c;
            if (disc < 0) return false;
            const double q = std::sqrt(disc);
            for (double cand : {-b - q, -b + q}) {
                if (cand > t_min && cand < t_max) {
                    t = cand;
                    n = (ray.at(t) - s->center) / s->radius;
                    return true;
                }
            }
            return false;
        }
        if (auto* p = std::get_if<scene::Plane>(&o.shape)) {
            const double dn = glm::dot(ray.dir, p->normal);
            if (std::fabs(dn) < 1e-12) return false;
            t = (p->distance - glm::dot(ray.origin, p->normal)) / dn;
            n = p->normal;
            return t > t_min && t < t_max;
        }
        return false;
    }
    const scene::Scene& scene_;
};

struct Image8 {
    int width = 0, height = 0;
    std::vector<int> rgb;  // 3 per pixel
    int at(int x, int y, int c) const { return rgb[(size_t(y) * width + x) * 3 + c]; }
};

// Renders `s` with the test intersector and encodes it as POV would write 8-bit pixels.
inline Image8 render8(const scene::Scene& s, int w, int h, RenderOptions opts = {}) {
    TestIntersector geometry(s);
    TraceOptions to;
    to.quality = opts.quality;
    to.indirect = opts.indirect;
    Tracer tracer(s, geometry, to);
    CameraModel camera(s.camera, w, h);
    opts.width = w;
    opts.height = h;
    BlockRenderer blocks(tracer, camera, opts, colour_compare_for(s, opts.aa_gamma));
    Image img;
    img.width = w;
    img.height = h;
    img.pixels.assign(size_t(w) * h * 5, 0.0f);
    ThreadState state;
    uint64_t primary = 0;
    const int bs = opts.block_size;
    for (int top = 0; top < h; top += bs)
        for (int left = 0; left < w; left += bs)
            blocks.render(left, top, std::min(w - 1, left + bs - 1), std::min(h - 1, top + bs - 1),
                          img, state, primary);
    Image8 out{w, h, {}};
    OutputOptions oo;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) out.rgb.push_back(encode_8bit(img.at(x, y)[c], s, oo));
    return out;
}

// Reads a binary PPM (skipping POV's '#' comment lines) from render/testdata.
inline Image8 read_reference(const std::string& name) {
    const std::string path =
        name.starts_with("/") ? name : std::string(LUMEN_SOURCE_DIR) + "/render/testdata/" + name;
    std::ifstream in(path, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t i = 0;
    std::vector<std::string> fields;
    while (fields.size() < 4 && i < data.size()) {
        while (i < data.size() && std::isspace((unsigned char)data[i])) ++i;
        if (i < data.size() && data[i] == '#') {
            while (i < data.size() && data[i] != '\n') ++i;
            continue;
        }
        size_t j = i;
        while (j < data.size() && !std::isspace((unsigned char)data[j])) ++j;
        fields.push_back(data.substr(i, j - i));
        i = j;
    }
    ++i;
    Image8 img;
    if (fields.size() < 4) return img;
    img.width = std::stoi(fields[1]);
    img.height = std::stoi(fields[2]);
    for (size_t k = i; k < data.size(); ++k) img.rgb.push_back((unsigned char)data[k]);
    return img;
}

struct Comparison {
    int differing = 0;  // channel values that differ
    int max_diff = 0;
    double psnr = 0;
};

inline Comparison compare(const Image8& a, const Image8& b) {
    Comparison c;
    double se = 0;
    const size_t n = std::min(a.rgb.size(), b.rgb.size());
    for (size_t i = 0; i < n; ++i) {
        const int d = std::abs(a.rgb[i] - b.rgb[i]);
        c.differing += d > 0;
        c.max_diff = std::max(c.max_diff, d);
        se += double(d) * d;
    }
    const double mse = n ? se / n : 0;
    c.psnr = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : 99;
    return c;
}

}  // namespace lumen::render::test

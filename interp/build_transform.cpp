// translate / rotate / scale / matrix / transform{}, and moving patterns with their owners.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "interp/build_common.hpp"

namespace lumen::interp {

using scene::Transform;

namespace {

// sin/cos of whole multiples of 90 degrees are exact, so `rotate z*90` gives clean numbers.
void sin_cos_degrees(double deg, double& s, double& c) {
    double quarter = deg / 90.0;
    if (quarter == std::floor(quarter)) {
        static const double sines[4] = {0, 1, 0, -1};
        int q = static_cast<int>(std::fmod(std::fmod(quarter, 4.0) + 4.0, 4.0));
        s = sines[q];
        c = sines[(q + 1) % 4];
        return;
    }
    double r = deg * M_PI / 180.0;
    s = std::sin(r);
    c = std::cos(r);
}

Transform from_matrix(const glm::dmat4& m) { return {m, glm::inverse(m)}; }

}  // namespace

Transform translation(const glm::dvec3& v) {
    return {glm::translate(glm::dmat4(1.0), v), glm::translate(glm::dmat4(1.0), -v)};
}

Transform rotation(const glm::dvec3& degrees) {
    glm::dmat4 m(1.0);
    for (int axis = 0; axis < 3; ++axis) {
        if (degrees[axis] == 0) continue;
        double s, c;
        sin_cos_degrees(degrees[axis], s, c);
        int a = (axis + 1) % 3, b = (axis + 2) % 3;  // the plane rotated: y,z / z,x / x,y
        glm::dmat4 r(1.0);
        r[a][a] = c;
        r[b][a] = -s;
        r[a][b] = s;
        r[b][b] = c;
        m = r * m;  // x first, then y, then z
    }
    return {m, glm::transpose(m)};
}

Transform scaling(const glm::dvec3& s) {
    return {glm::scale(glm::dmat4(1.0), s), glm::scale(glm::dmat4(1.0), 1.0 / s)};
}

Transform inverted(const Transform& t) { return {t.inv, t.m}; }

const std::vector<std::string>& transform_keywords() {
    static const std::vector<std::string> k = {"translate", "rotate", "scale", "matrix",
                                               "transform"};
    return k;
}

bool read_transform(ItemCursor& cur, const Item& kw, Transform& out) {
    if (kw.kind == Item::Kind::Value && kw.value.is<std::shared_ptr<const Transform>>()) {
        out = *kw.value.as<std::shared_ptr<const Transform>>();
        return true;
    }
    if (kw.kind != Item::Kind::Keyword) return false;
    const std::string& w = kw.keyword;
    if (w == "translate") {
        out = translation(cur.expect_vector(w));
    } else if (w == "rotate") {
        out = rotation(cur.expect_vector(w));
    } else if (w == "scale") {
        glm::dvec3 s = cur.expect_vector(w);
        for (int i = 0; i < 3; ++i) {
            if (s[i] == 0.0) {
                cur.warn(kw.loc, "zero scale component replaced by 1");
                s[i] = 1.0;
            }
        }
        out = scaling(s);
    } else if (w == "matrix") {
        if (!cur.next_is<VecN>()) cur.fail_expected("a 12-component vector", w);
        const Item& it = cur.next();
        const std::vector<double>& v = it.value.as<VecN>().c;
        if (v.size() != 12)
            cur.fail(it.loc, "matrix needs 12 values, found " + std::to_string(v.size()));
        glm::dmat4 m(1.0);
        // Rows of POV's 4x3 matrix act on row vectors: column j of glm holds row j of POV's.
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 3; ++i) m[j][i] = v[j * 3 + i];
        if (std::abs(glm::determinant(m)) < 1e-14) cur.fail(it.loc, "matrix is singular");
        out = from_matrix(m);
    } else if (w == "transform") {
        out = *cur.expect<std::shared_ptr<const Transform>>(w, "a transform");
    } else {
        return false;
    }
    return true;
}

Transform build_transform_block(ItemCursor& cur) {
    Transform total;
    bool invert = false;
    while (!cur.at_end()) {
        const Item& item = cur.next();
        Transform t;
        if (read_transform(cur, item, t)) {
            total = total.then(t);
        } else if (item.kind == Item::Kind::Keyword && item.keyword == "inverse") {
            invert = !invert;
        } else {
            std::vector<std::string> known = transform_keywords();
            known.push_back("inverse");
            cur.fail_unexpected(item, known);
        }
    }
    return invert ? inverted(total) : total;
}

// Not the pigment_map entries: they are evaluated at the pigment's pattern point, so they
// already move with it (render/pigment.cpp).
scene::PigmentPtr transformed(const scene::PigmentPtr& p, const Transform& t) {
    if (!p || p->pattern.uv_mapping) return p;
    auto copy = std::make_shared<scene::Pigment>(*p);
    copy->pattern.steps.add_transform(t);
    return copy;
}

// The normal_map entries are evaluated in this normal's pattern space (scene::Normal): they
// move with it without a copy of the transform.
scene::NormalPtr transformed(const scene::NormalPtr& n, const Transform& t) {
    if (!n || n->pattern.uv_mapping) return n;
    auto copy = std::make_shared<scene::Normal>(*n);
    copy->pattern.steps.add_transform(t);
    return copy;
}

// Nor the texture_map entries: they are evaluated at the texture's pattern point
// (render/texture_layers.cpp, render/tracer.cpp).
scene::TexturePtr transformed(const scene::TexturePtr& tex, const Transform& t) {
    if (!tex || tex->pattern.uv_mapping) return tex;
    auto copy = std::make_shared<scene::Texture>(*tex);
    transform_own(*copy, t);
    return copy;
}

void transform_own(scene::Texture& tex, const Transform& t) {
    tex.pigment = transformed(tex.pigment, t);
    tex.normal = transformed(tex.normal, t);
    tex.pattern.steps.add_transform(t);
}

scene::LayeredTexture transformed(const scene::LayeredTexture& layers, const Transform& t) {
    scene::LayeredTexture out;
    out.reserve(layers.size());
    for (const auto& l : layers) out.push_back(transformed(l, t));
    return out;
}

}  // namespace lumen::interp

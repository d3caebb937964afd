// The JSON tree the scene dump builds (interp/dump_scene.cpp, interp/dump_pattern.cpp) and
// the helpers that put values into it.
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/colour.hpp"
#include "scene/transform.hpp"
#include "scene/unsupported.hpp"

namespace lumen::interp::dump {

// A tiny JSON tree: built in key order, then printed.
// Object members are two parallel vectors (keys, values): a vector of pair<string, Json>
// needs Json complete, which clang's libstdc++ checks refuse.
struct Json {
    enum class Kind { Number, String, Bool, Array, Object } kind = Kind::Object;
    double number = 0;
    std::string text;
    bool flag = false;
    std::vector<Json> items;                             // Array
    std::vector<std::string> keys;                      // Object
    std::vector<Json> values;                           // Object, parallel to keys

    static Json num(double v) { Json j; j.kind = Kind::Number; j.number = v; return j; }
    static Json str(std::string s) { Json j; j.kind = Kind::String; j.text = std::move(s); return j; }
    static Json boolean(bool b) { Json j; j.kind = Kind::Bool; j.flag = b; return j; }
    static Json array() { Json j; j.kind = Kind::Array; return j; }

    bool empty() const { return kind == Kind::Object ? keys.empty() : kind == Kind::Array && items.empty(); }
    bool scalar() const { return kind != Kind::Array && kind != Kind::Object; }
    Json& put(const std::string& key, Json v) {
        keys.push_back(key);
        values.push_back(std::move(v));
        return *this;
    }
    Json& push(Json v) { items.push_back(std::move(v)); return *this; }
};

inline Json vec(const glm::dvec3& v) { return Json::array().push(Json::num(v.x)).push(Json::num(v.y)).push(Json::num(v.z)); }

inline Json colour(const scene::Colour& c) {
    Json a = Json::array();
    for (double v : {c.r, c.g, c.b, c.f, c.t}) a.push(Json::num(v));
    return a;
}

inline std::string loc_text(const SourceLoc& loc) {
    if (!loc.file) return loc.str();
    std::string name = loc.file->name;
    size_t slash = name.find_last_of('/');
    if (slash != std::string::npos) name = name.substr(slash + 1);
    return name + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column);
}

inline Json unsupported_text(const scene::Unsupported& u) {
    return Json::str(u.feature + " (" + loc_text(u.loc) + ")");
}

// Puts `key` only when the value differs from the default.
inline void put_if(Json& o, const std::string& key, double v, double def) {
    if (v != def) o.put(key, Json::num(v));
}
inline void put_if(Json& o, const std::string& key, bool v, bool def) {
    if (v != def) o.put(key, Json::boolean(v));
}
inline void put_if(Json& o, const std::string& key, const glm::dvec3& v, const glm::dvec3& def) {
    if (v != def) o.put(key, vec(v));
}
inline void put_if(Json& o, const std::string& key, const scene::Colour& v, const scene::Colour& def) {
    if (!(v == def)) o.put(key, colour(v));
}
inline void put_nonempty(Json& o, const std::string& key, Json v) {
    if (!v.empty()) o.put(key, std::move(v));
}

inline Json transform(const scene::Transform& t) {
    Json rows = Json::array();
    for (int r = 0; r < 3; ++r) {
        Json row = Json::array();
        for (int c = 0; c < 4; ++c) row.push(Json::num(t.m[c][r]));
        rows.push(row);
    }
    return rows;
}
inline void put_transform(Json& o, const scene::Transform& t) {
    if (!t.is_identity()) o.put("transform", transform(t));
}

}  // namespace lumen::interp::dump

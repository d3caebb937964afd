// Keyword tables. The reserved list is POV-Ray 3.7's "Reserved Keywords" table from the
// reference manual (plus `z`, `grey`, `lemon` and `mesh_camera`, which the table omits).
#include "parser/keywords.hpp"

#include <algorithm>
#include <unordered_set>

#include "parser/parser.hpp"
#include "scene/shape_list.hpp"

namespace lumen::parser {

namespace {

using WordSet = std::unordered_set<std::string_view>;

bool contains(const WordSet& set, std::string_view w) { return set.count(w) != 0; }

const WordSet& expression_words() {
    // Constants and built-in functions. `internal` is here because functions.inc calls it
    // like a function: `function { internal(42) }`.
    static const WordSet words = {
        "abs", "acos", "acosh", "asc", "asin", "asinh", "atan", "atan2", "atanh",
        "bitwise_and", "bitwise_or", "bitwise_xor", "ceil", "chr", "concat", "cos", "cosh",
        "defined", "degrees", "dimension_size", "dimensions", "div", "exp", "file_exists",
        "floor", "inside", "int", "ln", "log", "max", "min", "mod", "pow", "prod", "radians",
        "rand", "seed", "select", "sin", "sinh", "sqr", "sqrt", "str", "strcmp", "strlen",
        "strlwr", "substr", "strupr", "sum", "tan", "tanh", "val", "vaxis_rotate", "vcross",
        "vdot", "vlength", "vnormalize", "vrotate", "vstr", "vturbulence", "trace",
        "min_extent", "max_extent", "datetime", "now", "internal",
        "x", "y", "z", "t", "u", "v", "pi", "tau", "clock", "clock_delta", "clock_on", "true",
        "false", "yes", "no", "on", "off", "image_width", "image_height", "initial_clock",
        "final_clock", "initial_frame", "final_frame", "frame_number", "version",
        "input_file_name",
    };
    return words;
}

}  // namespace

const std::vector<std::string>& reserved_words() {
    static const std::vector<std::string> words = {
    "aa_level", "aa_threshold", "abs", "absorption", "accuracy", "acos", "acosh", "adaptive",
    "adc_bailout", "agate", "agate_turb", "albedo", "all", "all_intersections", "alpha",
    "altitude", "always_sample", "ambient", "ambient_light", "angle", "aoi", "aperture",
    "append", "arc_angle", "area_illumination", "area_light", "array", "asc", "ascii", "asin",
    "asinh", "assumed_gamma", "atan", "atan2", "atanh", "autostop", "average",
    "b_spline", "background", "bezier_spline", "bicubic_patch", "bitwise_and", "bitwise_or",
    "bitwise_xor", "black_hole", "blob", "blue", "blur_samples", "bokeh", "bounded_by", "box",
    "boxed", "bozo", "break", "brick", "brick_size", "brightness", "brilliance", "bump_map",
    "bump_size", "bumps", "camera", "case", "caustics", "ceil", "cells", "charset", "checker",
    "chr", "circular", "clipped_by", "clock", "clock_delta", "clock_on", "collect", "color",
    "color_map", "colour", "colour_map", "component", "composite", "concat", "cone",
    "confidence", "conic_sweep", "conserve_energy", "contained_by", "control0", "control1",
    "coords", "cos", "cosh", "count", "crackle", "crand", "cube", "cubic", "cubic_spline",
    "cubic_wave", "cutaway_textures", "cylinder", "cylindrical", "datetime", "debug", "declare",
    "default", "defined", "degrees", "density", "density_file", "density_map", "dents",
    "deprecated", "df3", "difference", "diffuse", "dimension_size", "dimensions", "direction",
    "disc", "dispersion", "dispersion_samples", "dist_exp", "distance", "div",
    "double_illuminate", "eccentricity", "else", "elseif", "emission", "end", "error",
    "error_bound", "evaluate", "exp", "expand_thresholds", "exponent", "exterior", "extinction",
    "face_indices", "facets", "fade_color", "fade_colour", "fade_distance", "fade_power",
    "falloff", "falloff_angle", "false", "fclose", "file_exists", "filter", "final_clock",
    "final_frame", "finish", "fisheye", "flatness", "flip", "floor", "focal_point", "fog",
    "fog_alt", "fog_offset", "fog_type", "fopen", "for", "form", "frame_number", "frequency",
    "fresnel", "function", "gamma", "gather", "gif", "global_lights", "global_settings",
    "gradient", "granite", "gray", "gray_threshold", "green", "grey", "height_field", "hexagon",
    "hf_gray_16", "hierarchy", "hollow", "hypercomplex", "if", "ifdef", "iff", "ifndef",
    "image_height", "image_map", "image_pattern", "image_width", "importance", "include",
    "initial_clock", "initial_frame", "input_file_name", "inside", "inside_vector", "int",
    "interior", "interior_texture", "internal", "interpolate", "intersection", "intervals",
    "inverse", "ior", "irid", "irid_wavelength", "isosurface", "jitter", "jpeg", "julia",
    "julia_fractal", "lambda", "lathe", "lemon", "leopard", "light_group", "light_source",
    "linear_spline", "linear_sweep", "ln", "load_file", "local", "location", "log", "look_at",
    "looks_like", "low_error_factor", "macro", "magnet", "major_radius", "mandel", "map_type",
    "marble", "material", "material_map", "matrix", "max", "max_extent", "max_gradient",
    "max_intersections", "max_iteration", "max_sample", "max_trace", "max_trace_level",
    "maximum_reuse", "media", "media_attenuation", "media_interaction", "merge", "mesh",
    "mesh2", "mesh_camera", "metallic", "method", "metric", "min", "min_extent",
    "minimum_reuse", "mm_per_unit", "mod", "mortar", "natural_spline", "nearest_count", "no",
    "no_bump_scale", "no_image", "no_radiosity", "no_reflection", "no_shadow",
    "noise_generator", "normal", "normal_indices", "normal_map", "normal_vectors", "now",
    "number_of_sides", "number_of_tiles", "number_of_waves", "object", "octaves", "off", "offset", "omega", "omnimax", "on", "once",
    "onion", "open", "orient", "orientation", "orthographic", "ovus", "panoramic", "parallel",
    "parametric", "pass_through", "pattern", "pavement", "perspective", "pgm", "phase", "phong",
    "phong_size", "photons", "pi", "pigment", "pigment_map", "pigment_pattern", "planar",
    "plane", "png", "point_at", "poly", "poly_wave", "polygon", "polynomial", "pot", "pow",
    "ppm", "precision", "precompute", "premultiplied", "pretrace_end", "pretrace_start",
    "prism", "prod", "projected_through", "pwr", "quadratic_spline", "quadric", "quartic",
    "quaternion", "quick_color", "quick_colour", "quilted", "radial", "radians", "radiosity",
    "radius", "rainbow", "ramp_wave", "rand", "range", "ratio", "read", "reciprocal",
    "recursion_limit", "red", "reflection", "reflection_exponent", "refraction", "render",
    "repeat", "rgb", "rgbf", "rgbft", "rgbt", "right", "ripples", "rotate", "roughness",
    "samples", "save_file", "scale", "scallop_wave", "scattering", "seed", "select",
    "shadowless", "sin", "sine_wave", "sinh", "sint16be", "sint16le", "sint32be", "sint32le",
    "sint8", "size", "sky", "sky_sphere", "slice", "slope", "slope_map", "smooth",
    "smooth_triangle", "solid", "sor", "spacing", "specular", "sphere", "sphere_sweep",
    "spherical", "spiral1", "spiral2", "spline", "split_union", "spotlight", "spotted", "sqr",
    "sqrt", "square", "srgb", "srgbf", "srgbft", "srgbt", "statistics", "str", "strcmp",
    "strength", "strlen", "strlwr", "strupr", "sturm", "substr", "subsurface", "sum",
    "superellipsoid", "switch", "sys", "t", "tan", "tanh", "target", "text", "texture",
    "texture_list", "texture_map", "tga", "thickness", "threshold", "tiff", "tightness",
    "tile2", "tiles", "tiling", "tolerance", "toroidal", "torus", "trace", "transform",
    "translate", "translucency", "transmit", "triangle", "triangle_wave", "triangular", "true",
    "ttf", "turb_depth", "turbulence", "type", "u", "u_steps", "uint16be", "uint16le", "uint8",
    "ultra_wide_angle", "undef", "union", "up", "use_alpha", "use_color", "use_colour",
    "use_index", "utf8", "uv_indices", "uv_mapping", "uv_vectors", "v", "v_steps", "val",
    "variance", "vaxis_rotate", "vcross", "vdot", "version", "vertex_vectors", "vlength",
    "vnormalize", "vrotate", "vstr", "vturbulence", "warning", "warp", "water_level", "waves",
    "while", "width", "wood", "wrinkles", "write", "x", "y", "yes", "z",
    };
    return words;
}

const std::vector<std::string>& block_keywords() {
    static const std::vector<std::string> words = scene::keywords_then(scene::kShapeKeywords, {
        "union", "merge", "intersection", "difference", "object", "camera", "light_source", "background", "global_settings",
        "sky_sphere", "fog", "rainbow", "texture", "pigment", "finish", "normal", "interior",
        "material", "media", "photons", "radiosity", "color_map", "colour_map", "pigment_map",
        "texture_map", "normal_map", "slope_map", "density_map", "material_map", "reflection",
        "irid", "isosurface", "parametric", "blob", "prism", "lathe", "sor", "superellipsoid",
        "text", "julia_fractal", "height_field", "bicubic_patch", "poly", "quartic", "cubic",
        "quadric", "lemon", "ovus", "sphere_sweep", "function", "spline", "transform", "warp",
        "image_map", "bump_map", "image_pattern", "vertex_vectors", "normal_vectors",
        "uv_vectors", "texture_list", "face_indices", "normal_indices", "uv_indices",
        "density", "contained_by", "clipped_by", "bounded_by", "looks_like",
        "projected_through", "light_group", "tiles", "pigment_pattern", "cutaway_textures",
        "interior_texture", "subsurface", "area_light", "mesh_camera", "pattern", "polynomial",
        "density_file", "component", "cubic_spline", "noise_generator", "gradient",
    });
    return words;
}

bool is_reserved(std::string_view word) {
    static const WordSet set = [] {
        WordSet s;
        for (const std::string& w : reserved_words()) s.insert(w);
        return s;
    }();
    return contains(set, word);
}

bool is_expression_word(std::string_view word) { return contains(expression_words(), word); }

bool is_colour_keyword(std::string_view word) { return word == "color" || word == "colour"; }

bool is_rgb_word(std::string_view word) {
    static const WordSet set = {"rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft"};
    return contains(set, word);
}

bool is_component_word(std::string_view word) {
    static const WordSet set = {"red", "green", "blue", "filter", "transmit", "gray", "grey"};
    return contains(set, word);
}

bool is_directive_word(std::string_view word) {
    static const WordSet set = {
        "version", "include", "declare", "local", "undef", "ifdef", "ifndef", "if", "elseif",
        "else", "end", "switch", "case", "range", "break", "while", "for", "macro", "default",
        "debug", "warning", "error", "render", "statistics", "fopen", "fclose", "read", "write",
    };
    return contains(set, word);
}

bool is_reserved_word(const std::string& word) { return is_reserved(word); }

}  // namespace lumen::parser

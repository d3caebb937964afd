// lumen's radiosity options (INI keys Radiosity_*, README "Radiosity"): how the patch solution
// is computed and shown. Unset values fall back to the scene's radiosity { } block.
#pragma once
#include <optional>
#include <string>

#include <glm/vec3.hpp>

namespace lumen::render::radiosity {

enum class Method { Auto, Matrix, Jacobi, GaussSeidel, Progressive };
enum class FormFactorMethod { RayCast, Analytic, Hemicube };
enum class DisplayMode { Gather, Preview };

// Adaptive subdivision of the receiving elements (receivers.hpp).
struct SubdivisionOptions {
    bool enabled = true;
    // An element splits when two corners' G differ (largest channel) by more than
    // `tolerance` × (their mean + 1/10 of the mean G the camera sees).
    double tolerance = 0.2;
    double min_element = 0;  // no split below this edge length; 0: patch size / 8
    double budget = 2;       // new vertices at most this × the vertex sides gathered
    // No split of an element whose longest edge spans fewer than `min_pixels` pixels where it
    // lies: smaller elements no longer change the image. The footprint of one pixel at p is
    // pixel_offset + pixel_angle × |p - eye| (set from the camera; pixel_angle 0: no limit).
    double min_pixels = 3;
    // A receiving element seen wider than `max_span` × the image width splits whatever its
    // corners say: gathers every few pixels of the image are what let the corners see light
    // that falls between them (one patch of a scene spread far can fill the view). 0: off.
    double max_span = 1.0 / 8;
    double image_width = 0;  // pixels, set from the render
    // The view: a child of a split element is seen when a corner, its centre or its point
    // nearest the eye lies within acos(view_cos) of view_dir (1: no test).
    glm::dvec3 view_dir{0, 0, 1};
    double view_cos = 1;
    double pixel_angle = 0, pixel_offset = 0;
    glm::dvec3 eye{0};
};

struct RadiosityOptions {
    std::optional<bool> enabled;   // Radiosity=on/off; unset: on when the scene has a block
    Method method = Method::Auto;  // auto: Jacobi when bounce-limited, else by patch count
    std::optional<int> bounces;    // unset: the scene's recursion_limit; 0: to convergence
    double patch_size = 0;         // largest element edge in scene units; 0: from the bounds
    FormFactorMethod form_factors = FormFactorMethod::RayCast;
    int ff_rays = 0;               // rays per vertex side for the solve's form factors; 0:
                                   // effective_ff_rays (scene_solution.hpp)
    int hemicube_res = 8;   // top face res x res, sides res x res/2: 192 rays at 8
    std::optional<int> gather_rays;     // final gather rays; unset: from the scene's count
    std::optional<double> cache_error;  // unset: from the scene's error_bound
    SubdivisionOptions subdivision;
    DisplayMode display = DisplayMode::Preview;  // gather needs a small cache error: slower
    double tolerance = 1e-4;  // stop of the iterative and progressive solvers (relative)
    // POV's +RF keys, here meaning the patch solution (not POV's irradiance cache).
    std::string file;
    bool from_file = false, to_file = false;
    // Radiosity_Store: a folder of solutions named by scene key, loaded where one is there and
    // saved after a solve, so that the processes of a farm share one solve (cli/farm.hpp).
    std::string store;
    bool verbose = false;  // +V: one line per phase on stderr
};

const char* method_name(Method m);
const char* form_factor_name(FormFactorMethod m);

}  // namespace lumen::render::radiosity

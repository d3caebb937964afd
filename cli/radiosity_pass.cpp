#include "cli/radiosity_pass.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "render/camera.hpp"

#include "render/radiosity/surface_light.hpp"
#include "render/radiosity/solution_io.hpp"
#include "render/radiosity/solution_key.hpp"

namespace lumen::cli {

namespace rad = render::radiosity;

namespace {

int render_threads(const render::RenderOptions& render) {
    return render.threads > 0 ? render.threads
                              : int(std::max(1u, std::thread::hardware_concurrency()));
}

std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f s", s);
    return buf;
}

}  // namespace

void apply_radiosity_switch(scene::Scene& scene, const rad::RadiosityOptions& o) {
    if (!o.enabled) return;
    if (!*o.enabled) scene.globals.radiosity.reset();
    else if (!scene.globals.radiosity) scene.globals.radiosity = scene::RadiositySettings{};
}

const render::IndirectLight* RadiosityPass::prepare(const scene::Scene& scene,
                                                    const rad::RadiosityOptions& options,
                                                    const render::RenderOptions& render,
                                                    std::vector<std::string>& log) {
    display_.reset();
    own_frame_ = std::make_unique<render::RenderFrame>(scene);
    return prepare(*own_frame_, options, render, log);
}

bool RadiosityPass::solve(const render::RenderFrame& frame, const rad::RadiosityOptions& options,
                          const render::RenderOptions& render, std::vector<std::string>& log) {
    const scene::Scene& scene = frame.scene();
    display_.reset();
    receivers_.reset();
    points_.reset();
    if (!scene.globals.radiosity) return false;
    options_ = options;
    mesh_ = std::make_unique<rad::SceneMesh>(
        rad::build_scene_mesh(frame.geometry(), options.patch_size, rad::ambient_emission(scene),
                              &scene.camera.location));
    for (const std::string& w : mesh_->warnings) log.push_back(w);

    const uint64_t key = rad::solution_key(frame, *mesh_, options);
    const size_t unknowns = mesh_->unknowns();
    const int bounces = rad::effective_bounces(scene, options);
    reused_ = false;
    loaded_from_.clear();
    const std::string stored = options.store.empty() ? std::string() : store_path(options.store, key);
    if (options.from_file && !options.file.empty()) {
        solution_ = rad::load_solution(options.file, key, unknowns);
        loaded_from_ = options.file;
    } else if (solution_ && solution_->scene_key == key && solution_->B.size() == unknowns &&
               bounces_ == bounces) {
        reused_ = true;  // only the camera changed: the solution is view-independent
    } else if (!stored.empty() && std::filesystem::exists(stored)) {
        solution_ = rad::load_solution(stored, key, unknowns);
        loaded_from_ = stored;
    } else {
        info_ = {};
        solution_ = rad::solve_scene(frame, *mesh_, options, render_threads(render), info_);
        solution_->scene_key = key;
        for (const std::string& w : info_.warnings) log.push_back(w);
        if (options.to_file && !options.file.empty()) rad::save_solution(*solution_, options.file);
        if (!stored.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(options.store, ec);
            rad::save_solution(*solution_, stored);
        }
    }
    bounces_ = bounces;
    return true;
}

std::string RadiosityPass::store_path(const std::string& folder, uint64_t key) {
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.rad", static_cast<unsigned long long>(key));
    return (std::filesystem::path(folder) / name).string();
}

const render::IndirectLight* RadiosityPass::prepare(const render::RenderFrame& frame,
                                                    const rad::RadiosityOptions& options,
                                                    const render::RenderOptions& render,
                                                    std::vector<std::string>& log) {
    if (!solve(frame, options, render, log)) return nullptr;
    const scene::Scene& scene = frame.scene();
    const render::Geometry& geometry = frame.geometry();
    const int threads = render_threads(render);

    const rad::DisplaySettings ds = rad::display_settings(scene, options);
    points_ = std::make_unique<rad::PointGather>(frame, *mesh_, &solution_->B,
                                                 rad::point_gather_settings(
                                                     scene, ds, bounces_,
                                                     options.display == rad::DisplayMode::Gather),
                                                 &solution_->indirect);
    if (options.display == rad::DisplayMode::Preview) {
        // The view-dependent part: a many-ray final gather at the vertices the camera sees
        // (the rest keep the solution's G, for reflections).
        const auto t0 = std::chrono::steady_clock::now();
        const render::CameraModel camera(scene.camera, render.width, render.height);
        const std::vector<char> seen =
            rad::visible_sides(*mesh_, geometry, camera, render.width, render.height, threads);
        gathered_ = size_t(std::count(seen.begin(), seen.end(), 1));
        rad::SubdivisionOptions subdivision = options.subdivision;
        // One pixel's footprint, from two neighbouring rays at the image's centre.
        const auto r0 = camera.ray(render.width / 2.0, render.height / 2.0);
        const auto r1 = camera.ray(render.width / 2.0 + 1, render.height / 2.0);
        if (r0 && r1) {
            const double c = glm::dot(glm::normalize(r0->dir), glm::normalize(r1->dir));
            subdivision.pixel_angle = std::acos(std::clamp(c, -1.0, 1.0));
            subdivision.pixel_offset = glm::length(r1->origin - r0->origin);
            subdivision.eye = r0->origin;
            subdivision.image_width = render.width;
            // The view cone, through the image's corners (a parallel camera has none).
            const glm::dvec3 centre = glm::normalize(r0->dir);
            double widest = 1;
            for (double cx : {0.0, double(render.width)})
                for (double cy : {0.0, double(render.height)})
                    if (const auto rc = camera.ray(cx, cy))
                        widest = std::min(widest, glm::dot(glm::normalize(rc->dir), centre));
            subdivision.view_dir = centre;
            subdivision.view_cos = widest > 0.9999 ? 1.0 : widest;
        }
        // Without form factors the solution's G (zeros when loaded from a file) stands in
        // for nothing: what the receivers do not gather, points gather.
        static const std::vector<glm::dvec3> none;
        receivers_ = std::make_unique<rad::ReceiverMesh>(
            rad::receive(scene, *mesh_, geometry, solution_->B, seen, ds.gather_rays, threads,
                         rad::needs_form_factors(scene, options) ? solution_->G : none,
                         subdivision, points_.get()));
        gather_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        display_ = rad::make_preview(*mesh_, *receivers_, points_.get(), ds);
    } else {
        display_ = rad::make_gather(*points_, ds);
    }
    return display_.get();
}

std::string RadiosityPass::summary() const {
    if (!mesh_ || !solution_) return {};
    std::string line = "radiosity: " + std::to_string(mesh_->elements.size()) + " patches, ";
    if (!loaded_from_.empty()) {
        line += "solution loaded from " + loaded_from_;
    } else if (reused_) {
        line += "solution reused (only the camera changed)";
    } else {
        const bool cube = options_.form_factors == rad::FormFactorMethod::Hemicube;
        line += (info_.ff_rays == 0 && !cube
                     ? std::string("no form factors (one bounce)")
                     : "form factors " + seconds(info_.form_factor_seconds) + " (" +
                           rad::form_factor_name(options_.form_factors) + " " +
                           (cube ? "resolution " + std::to_string(options_.hemicube_res)
                                 : std::to_string(info_.ff_rays) + " rays") +
                           ")") +
                ", solve " + seconds(info_.solve_seconds) +
                " (" + info_.method + " " + std::to_string(info_.iterations) + ")";
    }
    if (const auto* g = dynamic_cast<const rad::GatherStats*>(display_.get()))
        line += ", gather " + seconds(g->gather_seconds()) + " (" +
                std::to_string(g->cache_points()) + " cache points)";
    else
        line += ", gather " + seconds(gather_seconds_) + " (" + std::to_string(gathered_) +
                " vertices" +
                (receivers_ && receivers_->split
                     ? ", " + std::to_string(receivers_->split) + " elements split, " +
                           std::to_string(receivers_->added_vertices()) + " vertices added"
                     : std::string()) +
                ")";
    if (points_ && !dynamic_cast<const rad::GatherStats*>(display_.get()) && points_->cache_points())
        line += ", point gathers " + seconds(points_->gather_seconds()) + " (" +
                std::to_string(points_->cache_points()) + " cache points)";
    return line;
}

}  // namespace lumen::cli

#include "cli/run.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <new>
#include <optional>
#include <thread>

#include "cli/big_stack.hpp"
#include "cli/command_line.hpp"
#include "cli/farm.hpp"
#include "cli/frames.hpp"
#include "cli/merge.hpp"
#include "cli/progress.hpp"
#include "cli/radiosity_pass.hpp"
#include "cli/stop_signals.hpp"
#include "interp/dump_scene.hpp"
#include "base/diagnostics.hpp"
#include "parser/parser.hpp"
#include "base/stop_request.hpp"
#include "base/warning_log.hpp"
#include "render/frame.hpp"
#include "render/image_output.hpp"
#include "render/function_host.hpp"
#include "render/object_queries.hpp"

namespace lumen::cli {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

void print_diagnostic(const Diagnostic& d) { std::fputs(format_diagnostic(d).c_str(), stderr); }

// --check: one line per unsupported feature; the exit status says whether there were any.
int report_unsupported(const scene::Scene& scene) {
    for (const scene::Unsupported& u : scene.unsupported)
        std::printf("%s: error: '%s' is not supported yet\n", u.loc.str().c_str(),
                    u.feature.c_str());
    if (scene.unsupported.empty()) std::printf("no unsupported features\n");
    return scene.unsupported.empty() ? 0 : 1;
}

void render_frame(const Options& o, const Frame& frame, const scene::Scene& scene,
                  double parse_seconds, RadiosityPass& radiosity) {
    const bool terminal = isatty(fileno(stderr)) != 0;
    const std::string label = frame.number ? "frame " + std::to_string(frame.number) : "render";
    render::RenderStats stats;
    const auto start = Clock::now();
    render::RenderOptions options = effective_render_options(o);
    std::vector<std::string> log;
    const render::RenderFrame compiled(scene);  // one compiled scene for every pass
    options.indirect = radiosity.prepare(compiled, o.radiosity, options, log);
    for (const std::string& line : log) std::fprintf(stderr, "%s\n", line.c_str());
    ProgressBar bar(terminal, label);
    // Images are encoded block by block while they render: only the file write is left at
    // the end, which a whole image streams as its rows complete. A partial render's margins
    // are zero samples (alpha too), for lumen merge; Output_Crop leaves them out.
    std::optional<render::ImageEncoder> encoder;
    render::BlockDone encode_block;
    if (!frame.output.empty()) {
        const render::PixelArea a = render::render_area(options);
        const bool whole = render::covers_whole_image(options), crop = !whole && o.crop_output;
        if (crop) {
            encoder.emplace(scene, o.image, a.x1 - a.x0 + 1, a.y1 - a.y0 + 1);
            encoder->set_origin(a.x0, a.y0);
        } else {
            encoder.emplace(scene, o.image, options.width, options.height);
        }
        if (whole || crop) encoder->stream_to(frame.output);
        else encoder->clear_outside(a.x0, a.y0, a.x1, a.y1);
        encode_block = [&](const render::Image& im, int l, int t, int r, int b) {
            encoder->encode(im, l, t, r, b);
        };
    }
    const render::Image image = render::render(compiled, options, &stats,
                                               [&](double f) { bar.update(f); }, encode_block);
    const double render_seconds = seconds_since(start);
    bar.finish();
    for (const Diagnostic& d : compiled.geometry().shape_warnings()) print_diagnostic(d);
    if (o.verbose && options.indirect) std::fprintf(stderr, "%s\n", radiosity.summary().c_str());
    if (encoder) encoder->write(frame.output);
    const std::string photons =
        stats.photons_shot
            ? std::to_string(stats.photons_shot) + " photons shot (" +
                  std::to_string(stats.photons_stored) + " stored" +
                  (stats.media_photons_stored
                       ? ", " + std::to_string(stats.media_photons_stored) + " in media"
                       : "") +
                  "), "
            : "";
    std::fprintf(stderr, "lumen: %s%s: parsed in %s, rendered %dx%d in %s, %llu rays, %s%s\n",
                 o.input.c_str(), frame.number ? (" frame " + std::to_string(frame.number)).c_str() : "",
                 format_duration(parse_seconds).c_str(), image.width, image.height,
                 format_duration(render_seconds).c_str(),
                 static_cast<unsigned long long>(stats.total_rays), photons.c_str(),
                 frame.output.empty() ? "no file written (-F)" : ("wrote " + frame.output).c_str());
}

// --radiosity-only: the frame's patch solution, saved where the options say; no image.
void solve_radiosity(const Options& o, const Frame& frame, const scene::Scene& scene,
                     RadiosityPass& radiosity) {
    const auto start = Clock::now();
    const render::RenderFrame compiled(scene);
    std::vector<std::string> log;
    const bool solved = radiosity.solve(compiled, o.radiosity, effective_render_options(o), log);
    for (const std::string& line : log) std::fprintf(stderr, "%s\n", line.c_str());
    std::fprintf(stderr, "lumen: %s%s: %s in %s\n", o.input.c_str(),
                 frame.number ? (" frame " + std::to_string(frame.number)).c_str() : "",
                 !solved ? "no radiosity"
                 : radiosity.reused() ? "radiosity solution reused (only the camera changed)"
                 : !radiosity.loaded_from().empty()
                     ? ("radiosity solution loaded from " + radiosity.loaded_from()).c_str()
                     : "radiosity solved",
                 format_duration(seconds_since(start)).c_str());
}

}  // namespace

scene::Scene interpret_frame(const Options& o, const Frame& frame, SourceManager& sources,
                             const interp::WarningSink& warn,
                             const std::shared_ptr<scene::ObjectQueries>& object_queries) {
    interp::InterpOptions scene_options = frame.scene;
    scene_options.object_queries = object_queries;                  // trace() and inside()
    scene_options.function_host = render::shared_function_host();  // pigment functions
    // --check and --dump-scene end the process with their first frame; a render goes on.
    scene_options.leave_for_exit = o.process_ends && (o.check || o.dump_scene);
    if (!frame.output.empty())  // #fopen may write beside the image
        scene_options.io_folders.push_back(
            std::filesystem::absolute(frame.output).parent_path().string());
    scene::Scene scene = interp::interpret_file(sources, o.input, scene_options, warn);
    apply_radiosity_switch(scene, o.radiosity);
    return scene;
}

int run_frames(const Options& o, SourceManager& sources) {
    WarningLog warnings(print_diagnostic);  // a warning once per location, per frame
    const interp::WarningSink warn = [&](const Diagnostic& d) { warnings.report(d); };
    RadiosityPass radiosity;  // one solution serves frames where only the camera moves
    const auto object_queries = render::make_object_queries();
    for (const Frame& frame : plan_frames(o)) {
        const auto start = Clock::now();
        scene::Scene scene = interpret_frame(o, frame, sources, warn, object_queries);
        warnings.flush();
        const double parse_seconds = seconds_since(start);
        if (o.dump_scene) {
            std::fputs(interp::dump_scene_json(scene).c_str(), stdout);
            return 0;  // the first frame describes the scene
        }
        if (o.check) return report_unsupported(scene);
        if (o.radiosity_only) {
            solve_radiosity(o, frame, scene, radiosity);
            continue;
        }
        render_frame(o, frame, scene, parse_seconds, radiosity);
        throw_if_stop_requested();  // a signal during the file write: that frame is complete
    }
    return 0;
}

int run_guarded(const std::function<int(SourceManager&)>& work) {
    SourceManager sources;  // outlives every diagnostic, which points into its files
    try {
        int status = 0;
        const StopSignals signals;
        run_with_big_stack([&] { status = work(sources); });
        return status;
    } catch (const Interrupted& e) {
        std::fprintf(stderr, "lumen: stopped by %s; no image written for the unfinished frame\n",
                     e.signal == SIGINT ? "SIGINT" : e.signal == SIGTERM ? "SIGTERM" : "a signal");
        return stopped_exit_status(e.signal);
    } catch (const LumenError& e) {
        print_diagnostic(e.diag);
    } catch (const std::bad_alloc&) {
        std::fputs("lumen: error: out of memory\n", stderr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lumen: error: %s\n", e.what());
    }
    return 1;
}

int run_command_line(const std::vector<std::string>& args, bool process_ends) {
    if (!args.empty() && args[0] == "merge") return run_merge({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "farm") return run_farm({args.begin() + 1, args.end()});
    return run_guarded([&](SourceManager& sources) {
        Options o = parse_command_line(args, sources);
        o.process_ends = process_ends;
        if (o.help) {
            std::fputs(usage_text().c_str(), stdout);
            return 0;
        }
        if (o.version) {
            std::printf("lumen %s (POV-Ray 3.7 scene language)\n", LUMEN_VERSION);
            return 0;
        }
        for (const std::string& note : o.notes) std::fprintf(stderr, "%s\n", note.c_str());
        return run_frames(o, sources);
    });
}

}  // namespace lumen::cli

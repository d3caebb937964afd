// Public entry point of the interpreter: .pov file -> scene::Scene.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/diagnostics.hpp"
#include "base/source.hpp"
#include "function/vm.hpp"
#include "scene/object_queries.hpp"
#include "scene/scene.hpp"

namespace lumen::interp {

// Half of the physical memory, at most 8 GiB: the default heap limit of an evaluation.
size_t default_max_memory();

struct InterpOptions {
    // Include search order (POV-Ray's): the scene's folder, then these (+L / Library_Path),
    // then the installed POV-Ray include folder when `default_include_path` is set.
    std::vector<std::string> library_paths;
    bool default_include_path = true;
    std::string system_include_dir = "/usr/share/povray-3.7/include";
    // Folders, besides the working folder and the scene file's folder, where #fopen may read
    // and write (with their subfolders): the output folder and each Permitted_Path. Reading
    // may also use the library paths. POV-Ray 3.7 on Unix checks nothing; lumen refuses the
    // rest with a located error.
    std::vector<std::string> io_folders;
    // Declare=NAME=value: a float, or a string when quoted.
    struct Declare { std::string name; std::optional<double> number; std::string text; };
    std::vector<Declare> declares;
    // Animation and image identifiers visible to the scene.
    double clock = 0.0, clock_delta = 0.0, initial_clock = 0.0, final_clock = 1.0;
    int initial_frame = 1, final_frame = 1, frame_number = 0;
    int image_width = 320, image_height = 240;
    bool clock_on = false;  // clock_on identifier
    std::optional<double> version;  // +MV / Version=: initial #version
    // Limits (located errors, never crashes, hangs or exhausted memory; interp/budget.hpp;
    // INI keys Max_*). POV-Ray has none. The most that any of POV-Ray's 396 sample scenes
    // needs is noted beside each. A step costs 0.02-2 us: 1e8 steps end in seconds to minutes.
    long long max_loop_iterations = 10'000'000;  // per #while / #for / sum() / prod()
    long long max_steps = 100'000'000;           // loop iterations + macro/function calls (480710)
    size_t max_string_length = size_t(16) << 20;  // bytes per string (199)
    size_t max_array_elements = 10'000'000;       // per array (about 10000)
    size_t max_memory = default_max_memory();     // heap while evaluating, 0 = none (472 MB)
    int max_macro_depth = 200;
    int max_include_depth = 64;
    // Answers trace() and inside() (the renderer's, given by the caller); without it they are
    // reported as not supported.
    std::shared_ptr<scene::ObjectQueries> object_queries;
    // Evaluates pigment and pattern functions called while parsing (the renderer's, given by
    // the caller); without it such calls are errors.
    std::shared_ptr<const fn::Host> function_host;
    // The process exits once this scene has been used, and nothing is interpreted after it:
    // the evaluator and the syntax tree are then left for the exit to reclaim, not taken apart
    // node by node (as compilers skip freeing before they exit; `lumen --check` of the 15
    // standard includes spends 1.5-2 ms of its 18 ms there). Builds with AddressSanitizer free
    // them anyway, so that its leak check stays quiet.
    bool leave_for_exit = false;
};

using WarningSink = std::function<void(const Diagnostic&)>;

// Parses and evaluates `path`. Throws LumenError (with location and include chain) on the
// first error. Warnings go to `warn` (may be empty: then they are dropped).
scene::Scene interpret_file(SourceManager& sources, const std::string& path,
                            const InterpOptions& options, const WarningSink& warn = {});

// Same, from text already in memory (tests, fuzzing). `name` is used in messages.
scene::Scene interpret_text(SourceManager& sources, const std::string& name,
                            const std::string& text, const InterpOptions& options,
                            const WarningSink& warn = {});

}  // namespace lumen::interp

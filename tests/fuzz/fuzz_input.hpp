// One fuzz input through the interpreter and the scene builders with small limits, shared by
// the libFuzzer target (parse_fuzz.cpp) and the replay of its findings
// (interp/fuzz_regressions_test.cpp), so that a saved input fails the unit tests the same way.
#pragma once
#include <string>

#include "interp/dump_scene.hpp"
#include "interp/interpret.hpp"
#include "base/diagnostics.hpp"
#include "parser/parser.hpp"

namespace lumen::fuzz {

// Small enough that no input can run for seconds or take more than a few hundred MB.
inline interp::InterpOptions small_limits() {
    interp::InterpOptions o;
    o.max_loop_iterations = 2000;  // nested loops multiply: keep each one short
    o.max_steps = 50'000;  // a few s under ASan (200k macro calls took > 10 s, loaded)
    o.max_string_length = size_t(1) << 20;
    o.max_array_elements = 100'000;
    o.max_memory = size_t(1) << 30;
    o.max_macro_depth = 40;
    o.max_include_depth = 6;
    o.system_include_dir.clear();  // the standard includes are slow to fuzz through
    o.default_include_path = false;
    return o;
}

// Evaluates `text` as scene file `name` and dumps the scene (every field the builders set).
// Returns the dump, or the error's message; anything else escaping is a bug.
inline std::string evaluate(const std::string& name, const std::string& text) {
    SourceManager sources;
    try {
        const scene::Scene scene = interp::interpret_text(sources, name, text, small_limits());
        return interp::dump_scene_json(scene);
    } catch (const LumenError& e) {
        return format_diagnostic(e.diag);
    }
}

}  // namespace lumen::fuzz

// The seam between the core evaluator (directives, expressions, macros: interp/evaluator*)
// and the builders that turn flattened blocks into scene values (interp/build_*.cpp).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "interp/value.hpp"
#include "base/diagnostics.hpp"
#include "base/file_resolver.hpp"
#include "function/vm.hpp"

namespace lumen::interp {

// State the builders need from the evaluator.
struct BuildContext {
    double language_version = 3.62;  // #version in effect now
    bool version_given = false;       // a #version (or Version=) was seen
    std::optional<double> assumed_gamma;  // global_settings { assumed_gamma } read so far
    // #default { ... } settings; builders start new textures/pigments/finishes/normals from these.
    scene::PigmentPtr default_pigment;  // null = POV default (black)
    scene::FinishPtr default_finish;    // null = POV default finish
    scene::NormalPtr default_normal;    // null = none
    // Shared by every pattern of the scene, filled in by finish_scene (scene/pattern.hpp).
    std::shared_ptr<scene::PatternGlobals> pattern_globals =
        std::make_shared<scene::PatternGlobals>();
    bool noise_generator_given = false;  // global_settings { noise_generator } was read
    int noise_generator_read = 2;        // the value read
    // global_settings { charset utf8 | sys }: strings read later are UTF-8. POV-Ray 3.7's
    // default is ascii, whatever the #version.
    bool utf8_strings = false;
    std::function<void(const Diagnostic&)> warn;  // may be empty
    SearchPath search_path;  // where the files a scene names are looked for (density files)
    // Evaluates the float expression `expr` with x, y and z bound (a function image's body,
    // as in `height_field { function W, H { expr } }`); throws LumenError where it cannot.
    // Empty when no evaluator runs (tests that build hand-made items).
    std::function<double(const ast::Node& expr, double x, double y, double z)> eval_at;
    // What compiled functions run with at parse time: the noise_generator as it stands (the
    // scene's final one is only known at its end: interp/build_block.cpp).
    // Patterns read the scene's generator from the shared record, which holds the final one
    // only when the scene ends: while parsing, a pattern function sees the generator as it
    // stands, as in POV-Ray.
    fn::Context function_context() const {
        const int generator = noise_generator_given ? noise_generator_read
                              : language_version < 3.5 ? 1 : 2;
        if (pattern_globals) pattern_globals->noise_generator = generator;
        return {generator, function_host};
    }
    const fn::Host* function_host = nullptr;  // InterpOptions::function_host
};

// True for block keywords that the builders turn into values. Reserved words that are not
// supported give false: the evaluator then makes an Unsupported value without evaluating the
// block's contents.
bool is_supported_block(const std::string& keyword);
// Blocks whose items may be a pattern (pigment, texture, normal, density): in them an
// `object { }` is the object pattern.
bool is_pattern_owner(const std::string& keyword);

// All block keywords lumen knows (supported or not), for "did you mean" suggestions.
const std::vector<std::string>& known_block_keywords();

// Builds a flattened block into a value: `sphere` -> ObjectPtr, `texture` -> TextureValue,
// `pigment` -> PigmentPtr, ... Blocks that only mean something inside a parent (e.g.
// `vertex_vectors`, `reflection`, `radiosity`) come back as the BlockValue itself.
// Throws LumenError with the offending item's location.
Value build_block(BuildContext& ctx, const BlockValue& block);

// Applies one top-level item (an object, camera, light_source, global_settings, background,
// fog, sky_sphere, ...) to the scene. Throws LumenError for items that cannot stand at top level.
void apply_top_level(BuildContext& ctx, scene::Scene& scene, const Item& item);

// #default { ... }
void apply_default(BuildContext& ctx, const BlockValue& block);

// After the whole file ran: final fix-ups and the list of unsupported features in use.
void finish_scene(BuildContext& ctx, scene::Scene& scene);

}  // namespace lumen::interp

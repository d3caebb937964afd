// interpret_file / interpret_text: command-line declares, the main file's statements, and each
// top-level item handed to the scene builders.
#include "interp/interpret.hpp"

#include <filesystem>
#include <memory>

#include "base/sanitizers.hpp"
#include "interp/builders.hpp"
#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"
#include "parser/parser.hpp"

namespace lumen::interp {

namespace {

const char* item_word(const Item& item) {
    switch (item.kind) {
        case Item::Kind::Comma: return ",";
        case Item::Kind::MapEntry: return "[";
        default: return "";
    }
}

scene::Scene run(SourceManager& sources, const SourceFile& file, const InterpOptions& options,
                 const WarningSink& warn) {
    auto evaluator = std::make_unique<Evaluator>(sources, options, warn);
    Evaluator& ev = *evaluator;
    for (const InterpOptions::Declare& d : options.declares) {
        Value v = d.number ? Value{six_digits(*d.number), {}} : Value{d.text, {}};
        ev.symbols.declare(d.name, std::move(v));
    }
    ast::NodePtr tree = parser::parse_file(file);
    scene::Scene scene;
    ev.run_main(*tree, file, [&](const Item& item) {
        if (item.kind == Item::Kind::Keyword)
            throw LumenError(item.loc, "unexpected '" + item.keyword + "' at top level");
        if (item.kind != Item::Kind::Value)
            throw LumenError(item.loc, std::string("unexpected '") + item_word(item) + "' at top level");
        apply_top_level(ev.ctx, scene, item);
    });
    scene.language_version = ev.ctx.language_version;
    scene.version_given = ev.ctx.version_given;
    finish_scene(ev.ctx, scene);
    if (options.leave_for_exit && !LUMEN_ASAN) {
        (void)evaluator.release();
        (void)tree.release();
    }
    return scene;
}

}  // namespace

scene::Scene interpret_file(SourceManager& sources, const std::string& path,
                            const InterpOptions& options, const WarningSink& warn) {
    const SourceFile* file = sources.load(path);
    if (!file) throw LumenError(SourceLoc{}, "cannot read scene file '" + path + "'");
    InterpOptions with_scene_folder = options;  // user files may live beside the scene
    with_scene_folder.io_folders.push_back(
        std::filesystem::absolute(path).parent_path().string());
    return run(sources, *file, with_scene_folder, warn);
}

scene::Scene interpret_text(SourceManager& sources, const std::string& name, const std::string& text,
                            const InterpOptions& options, const WarningSink& warn) {
    return run(sources, *sources.add(name, text), options, warn);
}

}  // namespace lumen::interp

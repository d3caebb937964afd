// #include: POV's search order, a parse cache, a depth limit, and the include chain that
// every diagnostic raised inside an included file carries (innermost first).
#include <filesystem>

#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"
#include "base/file_resolver.hpp"
#include "parser/parser.hpp"

namespace lumen::interp {

std::string Evaluator::find_include(const std::string& name) const {
    SearchPath path{scene_dir_, options_.library_paths,
                    options_.default_include_path ? options_.system_include_dir : std::string()};
    return FileResolver(std::move(path)).find(name, FileResolver::Kind::Include);
}

const ast::Node& Evaluator::parse_file_cached(const std::string& path, SourceLoc from) {
    if (auto it = file_cache_.find(path); it != file_cache_.end()) return *it->second;
    const SourceFile* file = sources_.load(path);
    if (!file) throw LumenError(from, "cannot read include file '" + path + "'");
    trees_.push_back(parser::parse_file(*file));
    file_cache_[path] = trees_.back().get();
    return *trees_.back();
}

void Evaluator::include(const ast::Node& directive, std::vector<Item>& out) {
    Value name = eval(*directive.children.at(0));
    const std::string& file = to_string_value(name);
    std::string path = find_include(file);
    if (path.empty()) throw LumenError(name.loc, "cannot find include file '" + file + "'");
    if (include_depth_ >= options_.max_include_depth)
        throw LumenError(directive.loc, "include files nested more than " +
                                            std::to_string(options_.max_include_depth) + " deep");
    ScopedSet depth(include_depth_, include_depth_ + 1);
    try {
        const ast::Node& body = parse_file_cached(path, directive.loc);
        FrameGuard frame(symbols);  // #local in an include file stays in it
        std::vector<Item> items = flatten_sealed(body.children);
        out.insert(out.end(), std::make_move_iterator(items.begin()), std::make_move_iterator(items.end()));
    } catch (LumenError& e) {
        e.diag.include_chain.push_back(directive.loc);
        throw;
    }
}

}  // namespace lumen::interp

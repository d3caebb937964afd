// Flattening block bodies into items: the heart of the evaluation model (value.hpp).
#include <algorithm>
#include <string_view>

#include "interp/evaluator.hpp"
#include "interp/literal_items.hpp"
#include "parser/parser.hpp"

namespace lumen::interp {

using ast::Kind;

Evaluator::Evaluator(SourceManager& sources, const InterpOptions& options, WarningSink warn)
    : budget(options), sources_(sources), options_(options), warn_(std::move(warn)) {
    ctx.warn = warn_;
    ctx.function_host = options_.function_host.get();
    ctx.eval_at = [this](const ast::Node& expr, double x, double y, double z) {
        return eval_at(expr, x, y, z);
    };
    if (options_.version) {
        ctx.language_version = *options_.version;
        ctx.version_given = true;
    }
}

void Evaluator::warn(SourceLoc loc, const std::string& message, Severity sev) {
    if (warn_) warn_(Diagnostic{sev, loc, message, {}, {}});
}

void Evaluator::run_main(const ast::Node& body, const SourceFile& file,
                         const std::function<void(const Item&)>& emit) {
    size_t slash = file.name.rfind('/');
    scene_dir_ = slash == std::string::npos ? "." : file.name.substr(0, std::max<size_t>(slash, 1));
    ctx.search_path = {scene_dir_, options_.library_paths,
                       options_.default_include_path ? options_.system_include_dir : std::string()};
    ScopedSet sealed(breakable_, 0);
    std::vector<Item> items;
    for (const ast::NodePtr& n : body.children) {
        run_item(*n, items);
        expand_literals(items);
        for (const Item& it : items) emit(it);
        items.clear();
    }
}

std::vector<Item> Evaluator::flatten_sealed(const std::vector<ast::NodePtr>& nodes) {
    std::vector<Item> out;
    ScopedSet sealed(breakable_, 0);
    run_items(nodes, out);
    return out;
}

Flow Evaluator::run_items(const std::vector<ast::NodePtr>& nodes, std::vector<Item>& out) {
    for (const ast::NodePtr& n : nodes)
        if (run_item(*n, out) == Flow::Break) return Flow::Break;
    return Flow::Normal;
}

namespace {

Item value_item(Value v, SourceLoc loc) {
    Item it;
    it.kind = Item::Kind::Value;
    it.value = std::move(v);
    it.loc = loc;
    return it;
}

// The built-in function names julia_fractal also takes as bare keywords (its iteration).
bool is_julia_function_word(const std::string& w) {
    static constexpr std::string_view words[] = {
        "sqr", "exp", "ln", "sin", "asin", "sinh", "asinh", "cos", "acos", "cosh", "acosh",
        "tan", "atan", "tanh", "atanh"};
    return std::find(std::begin(words), std::end(words), w) != std::end(words);
}

Item keyword_item(const std::string& word, SourceLoc loc) {
    Item it;
    it.kind = Item::Kind::Keyword;
    it.keyword = word;
    it.loc = loc;
    return it;
}

}  // namespace

Flow Evaluator::run_item(const ast::Node& node, std::vector<Item>& out) {
    switch (node.kind) {
        case Kind::Keyword:
            out.push_back(keyword_item(node.text, node.loc));
            return Flow::Normal;
        case Kind::Comma: {
            Item it;
            it.kind = Item::Kind::Comma;
            it.loc = node.loc;
            out.push_back(std::move(it));
            return Flow::Normal;
        }
        case Kind::Semicolon:
        case Kind::Null:
            return Flow::Normal;
        case Kind::Literals: {
            Item it;
            it.kind = Item::Kind::Literals;
            it.loc = node.loc;
            it.literals = node.more().literals.get();
            out.push_back(std::move(it));
            return Flow::Normal;
        }
        case Kind::PolyTerm:  // the keyword `xyz`, then <i, j, k, c>
        case Kind::PwrTerm: {  // the keyword `pwr`, then <a, b>
            out.push_back(keyword_item(node.kind == Kind::PolyTerm ? "xyz" : "pwr", node.loc));
            VecN term;
            for (const auto& c : node.children) term.c.push_back(eval_float(*c));
            out.push_back(value_item(Value{std::move(term), node.loc}, node.loc));
            return Flow::Normal;
        }
        case Kind::MapEntry: {
            Item it;
            it.kind = Item::Kind::MapEntry;
            it.loc = node.loc;
            it.entry = flatten_sealed(node.children);
            expand_literals(it.entry);  // entries are short; their readers count values
            out.push_back(std::move(it));
            return Flow::Normal;
        }
        case Kind::Body:
            return run_items(node.children, out);
        case Kind::Call:
            // A macro call at item level splices its items in place.
            if (const ast::Node* m = macro_named(node.text)) {
                call_macro(*m, node, out);
                return Flow::Normal;
            }
            out.push_back(value_item(eval(node), node.loc));
            return Flow::Normal;
        case Kind::Ident:
            // `internal` is a function name in functions (`internal(42)`) and a keyword in
            // `text { internal 1 ... }`: bare at item level, it is the keyword. So are the
            // function names julia_fractal takes (`sin`, `sqr`, ...) without arguments.
            if (node.text == "internal" || is_julia_function_word(node.text)) {
                out.push_back(keyword_item(node.text, node.loc));
                return Flow::Normal;
            }
            [[fallthrough]];
        case Kind::Number: case Kind::String: case Kind::Vector:
        case Kind::Unary: case Kind::Binary: case Kind::Ternary: case Kind::Member:
        case Kind::Index: case Kind::Colour: case Kind::ArrayDecl: case Kind::Block: {
            if (node.kind == Kind::Block) block_item_ = &node;
            Value v = eval(node);
            out.push_back(value_item(std::move(v), node.loc));
            return Flow::Normal;
        }
        case Kind::ColourPart: case Kind::ArrayInit: case Kind::Branch: case Kind::Case:
        case Kind::Range:
            throw LumenError(node.loc, std::string("unexpected ") + ast::kind_name(node.kind));
        default:
            return run_directive(node, out);
    }
}

Value Evaluator::eval_block(const ast::Node& block) {
    const std::string& kw = block.text;
    if (kw == "function" || kw == "spline" || !block.more().params.empty()) return function_block(block);
    if (!is_supported_block(kw)) {
        if (parser::is_reserved_word(kw)) return Value{scene::Unsupported{kw, block.loc}, block.loc};
        throw LumenError(block.loc, "unknown keyword '" + kw + "'",
                         did_you_mean(kw, known_block_keywords()));
    }
    // `object { }` written as an item of a pigment, texture, normal or density is the object
    // pattern: its block is kept for the pattern to read (the object, then the list entries).
    const bool object_pattern = kw == "object" && &block == block_item_ && !open_blocks_.empty() &&
                                is_pattern_owner(open_blocks_.back());
    // A blob's `sphere { C, R, S }` and `cylinder { A, B, R, S }` are components, not shapes:
    // kept for the blob's reader (build_blob.cpp).
    const bool blob_component = (kw == "sphere" || kw == "cylinder") && &block == block_item_ &&
                                !open_blocks_.empty() && open_blocks_.back() == "blob";
    block_item_ = nullptr;
    return evaluate_block(block, kw, object_pattern || blob_component);
}

Value Evaluator::eval_block_as(const ast::Node& block, const std::string& keyword) {
    return evaluate_block(block, keyword, false);
}

Value Evaluator::evaluate_block(const ast::Node& block, const std::string& kw, bool keep) {
    open_blocks_.push_back(kw);
    struct Close {
        std::vector<std::string>& blocks;
        ~Close() { blocks.pop_back(); }
    } close{open_blocks_};
    BlockValue bv{kw, flatten_sealed(block.children), block.loc};
    if (keep) return Value{std::make_shared<const BlockValue>(std::move(bv)), block.loc};
    Value v = build_block(ctx, bv);
    if (v.loc.line == 0) v.loc = block.loc;
    return v;
}

}  // namespace lumen::interp

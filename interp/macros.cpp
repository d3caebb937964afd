// Macro calls. A macro body is parsed on first use (parse_fragment) and cached per Macro node.
// Arguments bind as #locals in a new frame; an argument written as a plain identifier is
// passed by reference: the parameter's final value is copied back to it (POV-Ray 3.7 does
// this even for `#local Param = ...`).
#include "interp/conditional_text.hpp"
#include "interp/evaluator.hpp"
#include "interp/literal_items.hpp"
#include "parser/parser.hpp"

namespace lumen::interp {

namespace {

// The location of byte `byte` of a macro body that starts at `start`.
SourceLoc location_in(const SourceFile& file, SourceLoc start, uint32_t byte) {
    SourceLoc loc = start;
    for (uint32_t i = start.byte; i < byte && i < file.text.size(); ++i) {
        if (file.text[i] == '\n') {
            ++loc.line;
            loc.column = 1;
        } else {
            ++loc.column;
        }
    }
    loc.byte = byte;
    return loc;
}

}  // namespace

const ast::Node* Evaluator::macro_named(const std::string& name) {
    Value* v = symbols.find(name);
    if (!v || !v->is<std::shared_ptr<const MacroValue>>()) return nullptr;
    return v->as<std::shared_ptr<const MacroValue>>()->node;
}

const ast::Node& Evaluator::parse_macro_body(const ast::Node& macro) {
    const auto it = macro_cache_.find(&macro);
    if (it != macro_cache_.end() && it->second) return *it->second;
    const SourceFile& file = *macro.loc.file;
    const ast::NodeExtra& m = macro.more();
    if (it == macro_cache_.end()) {
        try {
            trees_.push_back(parser::parse_fragment(file, m.raw_begin, m.raw_end, m.raw_loc));
            macro_cache_[&macro] = trees_.back().get();
            return *trees_.back();
        } catch (const LumenError&) {
            macro_cache_[&macro] = nullptr;  // no tree as written
        }
    }
    if (const ast::Node* body = parse_decided_macro_body(macro)) return *body;
    // Nothing decided helps: report the body's own syntax error.
    trees_.push_back(parser::parse_fragment(file, m.raw_begin, m.raw_end, m.raw_loc));
    return *trees_.back();
}

// A body with no tree as written, parsed with the conditions it can decide now decided
// (interp/conditional_text.hpp): a condition counts only if it reads no variable the body
// assigns and calls no macro and no rand() (whose stream advances each time it runs), so
// deciding it at the call gives what running it would.
// One tree per outcome, kept for later calls.
const ast::Node* Evaluator::parse_decided_macro_body(const ast::Node& macro) {
    const SourceFile& file = *macro.loc.file;
    const ast::NodeExtra& m = macro.more();
    const ConditionalScan scan = scan_conditionals(file.text, m.raw_begin, m.raw_end);
    const auto decide = [&](uint32_t begin, uint32_t end) -> std::optional<bool> {
        const std::string_view condition(file.text.data() + begin, end - begin);
        for (const std::string& name : condition_identifiers(condition))
            if (scan.assigned.count(name) || macro_named(name) || name == "rand") return std::nullopt;
        try {
            const ast::NodePtr expr = parser::parse_expression(
                file, begin, end, location_in(file, m.raw_loc, begin));
            return eval_condition(*expr);
        } catch (const LumenError&) {
            return std::nullopt;
        }
    };
    std::optional<std::string> text = blank_decided_conditionals(file.text, scan, decide);
    if (!text) return nullptr;
    std::string key = text->substr(m.raw_begin, m.raw_end - m.raw_begin);
    const auto found = decided_macro_bodies_.find({&macro, key});
    if (found != decided_macro_bodies_.end()) return found->second;
    const SourceFile* decided = sources_.add(file.name, std::move(*text));
    try {
        trees_.push_back(parser::parse_fragment(*decided, m.raw_begin, m.raw_end, m.raw_loc));
    } catch (const LumenError&) {
        return nullptr;
    }
    decided_macro_bodies_[{&macro, std::move(key)}] = trees_.back().get();
    return trees_.back().get();
}

void Evaluator::call_macro(const ast::Node& macro, const ast::Node& call, std::vector<Item>& out) {
    const auto& params = macro.more().params;
    // Arguments are evaluated in the caller's scope, before the new frame exists.
    std::vector<Value> args;
    struct Reference { size_t param; std::string name; size_t frame; };
    std::vector<Reference> refs;
    for (const ast::NodePtr& a : call.children) {
        if (a->kind == ast::Kind::Ident && symbols.find(a->text))
            refs.push_back({args.size(), a->text, symbols.frame_of(a->text)});
        eval_argument(*a, args);
    }
    const size_t given = args.size();
    if (given > params.size())
        throw LumenError(call.loc, "macro '" + macro.text + "' expects " + std::to_string(params.size()) +
                                       " argument(s), found " + std::to_string(given));
    for (size_t i = given; i < params.size(); ++i)
        if (i >= macro.more().optional_params.size() || !macro.more().optional_params[i])
            throw LumenError(call.loc, "macro '" + macro.text + "' needs a value for parameter '" +
                                           params[i] + "'");
    if (macro_depth_ >= options_.max_macro_depth)
        throw LumenError(call.loc, "macro '" + macro.text + "' nested more than " +
                                       std::to_string(options_.max_macro_depth) + " calls deep");
    budget.step(call.loc);

    ScopedSet depth(macro_depth_, macro_depth_ + 1);
    ScopedSet inside(breakable_, 1);  // #break ends the macro
    std::vector<std::pair<Reference, Value>> results;
    {
        FrameGuard frame(symbols);
        for (size_t i = 0; i < given; ++i) symbols.local(params[i], std::move(args[i]));
        // Parsed in the new frame: a body may need its conditions decided (parse_decided_macro_body).
        const ast::Node& body = parse_macro_body(macro);
        run_items(body.children, out);
        for (const Reference& r : refs) {
            const std::string& p = params[r.param];
            if (symbols.frame_of(p) == symbols.depth() - 1) results.push_back({r, *symbols.find(p)});
        }
    }
    // Copy by-reference parameters back into the caller's variables.
    for (auto& [r, v] : results)
        if (r.frame < symbols.depth()) symbols.set_in_frame(r.frame, r.name, std::move(v));
}

Value Evaluator::call_macro_value(const ast::Node& macro, const ast::Node& call) {
    std::vector<Item> items;
    call_macro(macro, call, items);
    expand_literals(items);
    if (items.size() != 1 || items[0].kind != Item::Kind::Value)
        throw LumenError(call.loc, "macro '" + macro.text + "' used in an expression produced " +
                                       std::to_string(items.size()) + " items");
    Value v = std::move(items[0].value);
    return v;
}

}  // namespace lumen::interp

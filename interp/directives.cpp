// Directives: #version #declare #local #undef #if #ifdef #ifndef #switch #while #for #break
// #macro (definition) #default #debug #warning #error, and the refused file I/O directives.
#include <cmath>

#include "interp/conversions.hpp"
#include "interp/evaluator.hpp"
#include "interp/literal_items.hpp"

namespace lumen::interp {

using ast::Kind;

Flow Evaluator::run_directive(const ast::Node& n, std::vector<Item>& out) {
    switch (n.kind) {
        case Kind::Version:
            ctx.language_version = eval_float(*n.children.at(0));
            ctx.version_given = true;
            return Flow::Normal;
        case Kind::Include: include(n, out); return Flow::Normal;
        case Kind::Declare: declare(n); return Flow::Normal;
        case Kind::Undef:
            if (!symbols.undef(n.text)) warn(n.loc, "#undef of '" + n.text + "', which is not declared");
            return Flow::Normal;
        case Kind::If: return run_if(n, out);
        case Kind::Ifdef: return run_ifdef(n, out);
        case Kind::Switch: return run_switch(n, out);
        case Kind::Break:
            if (breakable_ == 0) throw LumenError(n.loc, "#break outside #switch, #while, #for or a macro");
            return Flow::Break;
        case Kind::While: run_while(n, out); return Flow::Normal;
        case Kind::For: run_for(n, out); return Flow::Normal;
        case Kind::Macro:
            symbols.declare(n.text, Value{std::make_shared<const MacroValue>(MacroValue{&n}), n.loc});
            return Flow::Normal;
        case Kind::Default: {
            BlockValue block{"default", flatten_sealed(n.children), n.loc};
            apply_default(ctx, block);
            return Flow::Normal;
        }
        case Kind::Message: message(n); return Flow::Normal;
        case Kind::FileIO: file_io(n); return Flow::Normal;
        default:
            throw LumenError(n.loc, std::string("unexpected ") + ast::kind_name(n.kind));
    }
}

// The value of a #declare's right-hand side, children[rhs..]. POV also allows a directive
// there (`#declare S = #if (A) sphere {...} #else box {...} #end`), so the right-hand side
// is run like a block body: it must give one value, or several textures (a layered texture).
Value Evaluator::declared_value(const ast::Node& n, size_t rhs) {
    if (n.children.size() <= rhs) throw LumenError(n.loc, "#" + n.text + " needs a value");
    std::vector<Item> items;
    if (n.children.size() == rhs + 1 && n.children[rhs]->kind != Kind::Call) {
        if (run_item(*n.children[rhs], items) == Flow::Break)
            throw LumenError(n.loc, "#break in the value of a #" + n.text);
    } else {
        for (size_t i = rhs; i < n.children.size(); ++i) {
            Item it;
            it.value = eval(*n.children[i]);
            it.loc = n.children[i]->loc;
            items.push_back(std::move(it));
        }
    }
    expand_literals(items);
    if (items.size() == 1 && items[0].kind == Item::Kind::Value) {
        Value v = std::move(items[0].value);
        if (v.is<std::shared_ptr<ArrayValue>>())  // assignment copies an array
            v.v = std::make_shared<ArrayValue>(*v.as<std::shared_ptr<ArrayValue>>());
        if (v.is<std::monostate>()) throw LumenError(items[0].loc, "this produces no value to #" + n.text);
        return v;
    }
    if (items.empty()) throw LumenError(n.loc, "#" + n.text + " of '" + n.children[rhs - 1]->text + "' has no value");
    auto layered = std::make_shared<TextureValue>();
    for (const Item& it : items) {
        if (it.kind != Item::Kind::Value || !it.value.is<std::shared_ptr<const TextureValue>>())
            throw LumenError(it.loc, "#" + n.text + " needs one value (several are allowed only for layered textures)");
        const auto& layers = it.value.as<std::shared_ptr<const TextureValue>>()->layers;
        layered->layers.insert(layered->layers.end(), layers.begin(), layers.end());
    }
    return Value{std::shared_ptr<const TextureValue>(std::move(layered)), items[0].loc};
}

// POV-Ray keeps a function's identifier until #undef: a function is not redeclared (a #local
// in a macro binds a new name), nor does another kind of identifier become a function.
void Evaluator::check_function_redeclaration(const ast::Node& target, bool local,
                                             const Value& v) {
    const size_t frame = symbols.frame_of(target.text);
    if (frame == SymbolTable::npos || (local && frame + 1 != symbols.depth())) return;
    const Value& old = *symbols.find(target.text);
    using Fn = std::shared_ptr<const FunctionValue>;
    if (old.is<Fn>())
        throw LumenError(target.loc, "Redeclaring functions is not allowed - #undef the function first!");
    if (v.is<Fn>())
        throw LumenError(target.loc, std::string("Attempted to redefine ") + old.type_name() +
                                         " identifier as function identifier.");
}

void Evaluator::declare(const ast::Node& n) {
    bool local = n.text == "local";
    // `#declare deprecated [once] "message" Name = ...`: the parser keeps the message first.
    size_t first = !n.children.empty() && n.children[0]->kind == Kind::String ? 1 : 0;
    const ast::Node& target = *n.children.at(first);
    Value v = declared_value(n, first + 1);
    if (target.kind == Kind::Ident) {
        check_function_redeclaration(target, local, v);
        if (local) symbols.local(target.text, std::move(v));
        else symbols.declare(target.text, std::move(v));
        return;
    }
    if (target.kind != Kind::Index) throw LumenError(target.loc, "expected an identifier to #" + n.text);
    ArraySlot slot = array_slot(target);
    slot.array->elems[slot.index] = std::move(v);
}

Flow Evaluator::run_if(const ast::Node& n, std::vector<Item>& out) {
    for (const auto& branch : n.children) {
        const ast::Node& cond = *branch->children.at(0);
        if (cond.kind == Kind::Null || eval_condition(cond))
            return run_item(*branch->children.at(1), out);
    }
    return Flow::Normal;
}

Flow Evaluator::run_ifdef(const ast::Node& n, std::vector<Item>& out) {
    bool defined = is_defined(*n.children.at(0));
    if (n.text == "ifndef") defined = !defined;
    // children[1] / [2] are Branch nodes: {Null, Body}.
    if (defined) return run_item(*n.children.at(1)->children.at(1), out);
    if (n.children.size() > 2) return run_item(*n.children[2]->children.at(1), out);
    return Flow::Normal;
}

// POV's #switch falls through: once a clause matches, the following clause bodies run too
// (whatever their conditions) until a #break or the #end (checked against POV-Ray 3.7).
Flow Evaluator::run_switch(const ast::Node& n, std::vector<Item>& out) {
    double selector = eval_float(*n.children.at(0));
    bool matched = false;
    ScopedSet inside(breakable_, breakable_ + 1);
    for (size_t i = 1; i < n.children.size(); ++i) {
        const ast::Node& clause = *n.children[i];
        if (!matched) {
            if (clause.kind == Kind::Case)
                matched = std::fabs(selector - eval_float(*clause.children.at(0))) < kEpsilon;
            else if (clause.kind == Kind::Range)
                matched = selector >= eval_float(*clause.children.at(0)) &&
                          selector <= eval_float(*clause.children.at(1));
            else
                matched = true;  // #else
        }
        if (matched && run_item(*clause.children.back(), out) == Flow::Break) break;
    }
    return Flow::Normal;
}

void Evaluator::loop_limit(long long& iterations, const ast::Node& node, const char* what) {
    if (++iterations > options_.max_loop_iterations)
        throw LumenError(node.loc, std::string(what) + " loop exceeded " +
                                       std::to_string(options_.max_loop_iterations) +
                                       " iterations (limit Max_Loop_Iterations): an endless loop?");
    budget.step(node.loc);
}

Flow Evaluator::run_loop_body(const ast::Node& body, std::vector<Item>& out) {
    ScopedSet inside(breakable_, breakable_ + 1);
    return run_item(body, out);
}

void Evaluator::run_while(const ast::Node& n, std::vector<Item>& out) {
    long long iterations = 0;
    while (eval_condition(*n.children.at(0))) {
        loop_limit(iterations, n, "#while");
        if (run_loop_body(*n.children.at(1), out) == Flow::Break) return;
    }
}

// #for (I, start, end [, step]): I is a local; the body may change it (POV reads it back
// each time), and the end test allows for rounding (0 to 0.3 step 0.1 runs 4 times).
void Evaluator::run_for(const ast::Node& n, std::vector<Item>& out) {
    double start = eval_float(*n.children.at(0));
    double end = eval_float(*n.children.at(1));
    const ast::Node& step_node = *n.children.at(2);
    double step = step_node.kind == Kind::Null ? 1.0 : eval_float(step_node);
    if (step == 0 || !std::isfinite(step)) throw LumenError(step_node.loc, "#for step must not be 0");
    const std::string& var = n.text;
    symbols.local(var, Value{start, n.loc});
    long long iterations = 0;
    for (;;) {
        Value* cur = symbols.find(var);
        if (!cur) throw LumenError(n.loc, "#for loop variable '" + var + "' was #undef'd");
        double i = to_float(*cur);
        if (step > 0 ? i > end + kEpsilon : i < end - kEpsilon) return;
        loop_limit(iterations, n, "#for");
        if (run_loop_body(*n.children.at(3), out) == Flow::Break) return;
        cur = symbols.find(var);
        if (!cur) throw LumenError(n.loc, "#for loop variable '" + var + "' was #undef'd");
        *cur = Value{to_float(*cur) + step, n.loc};
    }
}

void Evaluator::message(const ast::Node& n) {
    Value v = eval(*n.children.at(0));
    const std::string& text = to_string_value(v);
    if (n.text == "error") throw LumenError(n.loc, text.empty() ? "#error" : text);
    warn(n.loc, text, n.text == "warning" ? Severity::Warning : Severity::Note);
}

}  // namespace lumen::interp

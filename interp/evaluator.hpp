// The core SDL evaluator: runs directives, expands macros, evaluates expressions and flattens
// block bodies into items (see value.hpp for the model). One Evaluator interprets one scene.
//
// The work is split by concept: flatten.cpp (items and blocks), expressions.cpp, builtins.cpp,
// directives.cpp, macros.cpp, user_functions.cpp, includes.cpp; scope.hpp holds the symbol
// tables and conversions.hpp the promotion rules. Recursion follows the syntax tree, whose nesting
// the parser bounds, plus macro calls and includes, which have their own depth limits.
#pragma once
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "function/vm.hpp"
#include "interp/budget.hpp"
#include "interp/builders.hpp"
#include "interp/interpret.hpp"
#include "interp/scope.hpp"
#include "interp/value.hpp"

namespace lumen::interp {

// Sets a variable for the lifetime of the guard (depth counters, the #break permission).
template <class T>
class ScopedSet {
public:
    ScopedSet(T& ref, T value) : ref_(ref), saved_(ref) { ref_ = value; }
    ~ScopedSet() { ref_ = saved_; }
    ScopedSet(const ScopedSet&) = delete;
    ScopedSet& operator=(const ScopedSet&) = delete;

private:
    T& ref_;
    T saved_;
};

// A new symbol frame (macro call, include file) for the lifetime of the guard.
class FrameGuard {
public:
    explicit FrameGuard(SymbolTable& s) : s_(s) { s_.push(); }
    ~FrameGuard() { s_.pop(); }
    FrameGuard(const FrameGuard&) = delete;
    FrameGuard& operator=(const FrameGuard&) = delete;

private:
    SymbolTable& s_;
};

// How a directive body ended: normally, or unwinding a #break.
enum class Flow { Normal, Break };

class Evaluator {
public:
    Evaluator(SourceManager& sources, const InterpOptions& options, WarningSink warn);

    // Runs a parsed main file (or text) at top level, handing each top-level item to `emit`
    // as soon as its statement has run. Includes are searched in `file`'s folder first.
    void run_main(const ast::Node& body, const SourceFile& file,
                  const std::function<void(const Item&)>& emit);

    // ---- items and blocks (flatten.cpp) ------------------------------------------------------
    // Runs the items of a Body (or any node list), appending results to `out`.
    Flow run_items(const std::vector<ast::NodePtr>& nodes, std::vector<Item>& out);
    Flow run_item(const ast::Node& node, std::vector<Item>& out);
    // A block body where #break cannot reach outside (blocks, includes, the main file).
    std::vector<Item> flatten_sealed(const std::vector<ast::NodePtr>& nodes);
    // `sphere { ... }` -> built value; function/spline -> FunctionValue; reserved but
    // unsupported -> Unsupported; unknown word -> error.
    Value eval_block(const ast::Node& block);

    // ---- expressions (expressions.cpp) -------------------------------------------------------
    Value eval(const ast::Node& expr);
    // `e`'s operands from `from` on folded into `acc` (what `e` computed before them).
    Value fold_binary(const ast::Node& e, size_t from, Value acc);
    // A macro argument or #write item, or two where a value that is not a number (an object,
    // a string) is followed by a signed term with no comma: POV-Ray ends the item there.
    void eval_argument(const ast::Node& arg, std::vector<Value>& args);
    double eval_float(const ast::Node& expr);
    bool eval_condition(const ast::Node& expr);
    Value lookup(const ast::Node& ident);  // identifier or built-in constant
    // Declared names and reserved words, for "did you mean" hints.
    std::vector<std::string> suggestion_words() const;
    // The array element an Index node names (bounds checked; may be uninitialised).
    struct ArraySlot {
        std::shared_ptr<ArrayValue> array;
        size_t index;
    };
    ArraySlot array_slot(const ast::Node& index);

    // ---- built-ins (builtins.cpp) ------------------------------------------------------------
    std::optional<Value> builtin_constant(const std::string& name, SourceLoc loc) const;
    static bool is_builtin_function(const std::string& name);
    Value call_builtin(const ast::Node& call);
    double new_rand_stream(const Value& seed);          // seed()
    double next_rand(const Value& stream);        // rand()
    Value fold_range(const ast::Node& call, bool product);  // sum() / prod()
    bool is_defined(const ast::Node& target);    // #ifdef, defined(): Ident or Index

    // ---- directives (directives.cpp) ---------------------------------------------------------
    Flow run_directive(const ast::Node& node, std::vector<Item>& out);

    // ---- macros (macros.cpp) -----------------------------------------------------------------
    // `call` is a Call node naming macro `m`. Items go to `out`.
    void call_macro(const ast::Node& macro, const ast::Node& call, std::vector<Item>& out);
    // A macro call used as a value: must produce exactly one value item.
    Value call_macro_value(const ast::Node& macro, const ast::Node& call);
    // A user-defined function called in an expression (user_functions.cpp).
    Value call_function(const FunctionValue& fn, const ast::Node& call);
    Value call_spline(const fn::Spline& spline, const ast::Node& call);
    // A `function { }` or `spline { }` block as a FunctionValue (user_functions.cpp).
    Value function_block(const ast::Node& block);
    // A `function { }` block's body compiled (compile_function.cpp); located errors.
    fn::ProgramPtr compile_function(const ast::Node& block);
    // `function { pigment | pattern | transform { } }`.
    fn::ProgramPtr compile_vector_function(const ast::Node& block);
    // A block evaluated as if its keyword were `keyword` (a pattern function's pattern block
    // read as a pigment).
    Value eval_block_as(const ast::Node& block, const std::string& keyword);
    // The context compiled functions run in at parse time (the current noise_generator).
    fn::Context function_context() const;
    // `expr` evaluated as a function body with x, y, z bound (BuildContext::eval_at).
    double eval_at(const ast::Node& expr, double x, double y, double z);
    // The Macro node a name refers to, or null.
    const ast::Node* macro_named(const std::string& name);

    // ---- includes (includes.cpp) -------------------------------------------------------------
    void include(const ast::Node& directive, std::vector<Item>& out);
    // Resolves an include name with POV's search order; empty if not found.
    std::string find_include(const std::string& name) const;

    void warn(SourceLoc loc, const std::string& message, Severity sev = Severity::Warning);

    const InterpOptions& options() const { return options_; }
    // True while a function { } body is evaluated: POV-Ray's function VM checks no domains.
    bool in_function_body() const { return in_function_body_; }
    BuildContext ctx;
    Budget budget;  // steps and memory of the whole run
    SymbolTable symbols;

private:
    // The block built as `kw`, or kept as a BlockValue for its owner to read (`keep`).
    Value evaluate_block(const ast::Node& block, const std::string& kw, bool keep);
    Value member(const ast::Node& e);
    Value colour(const ast::Node& e);
    Value array_decl(const ast::Node& e);
    void fill_array(ArrayValue& arr, const ast::Node& init, size_t level, size_t& next);

    void declare(const ast::Node& node);
    void check_function_redeclaration(const ast::Node& target, bool local, const Value& v);
    Value declared_value(const ast::Node& node, size_t rhs);
    Flow run_if(const ast::Node& node, std::vector<Item>& out);
    Flow run_ifdef(const ast::Node& node, std::vector<Item>& out);
    Flow run_switch(const ast::Node& node, std::vector<Item>& out);
    void run_while(const ast::Node& node, std::vector<Item>& out);
    void run_for(const ast::Node& node, std::vector<Item>& out);
    Flow run_loop_body(const ast::Node& body, std::vector<Item>& out);
    void message(const ast::Node& node);
    // #fopen / #fclose / #read / #write (interp/file_io.cpp).
    void file_io(const ast::Node& node);
    std::shared_ptr<FileValue> open_file(const ast::Node& node);
    std::shared_ptr<FileValue> file_named(const ast::Node& handle, bool writing);
    void close_file(const std::string& id);
    void write_file(const ast::Node& node);
    void read_file(const ast::Node& node);
    void loop_limit(long long& iterations, const ast::Node& node, const char* what);

    const ast::Node& parse_macro_body(const ast::Node& macro);
    const ast::Node* parse_decided_macro_body(const ast::Node& macro);
    const ast::Node& parse_file_cached(const std::string& path, SourceLoc from);

    SourceManager& sources_;
    const InterpOptions& options_;
    WarningSink warn_;
    std::string scene_dir_;
    int macro_depth_ = 0;
    int include_depth_ = 0;
    bool in_function_body_ = false;
    int breakable_ = 0;  // > 0 inside #switch/#while/#for/macro bodies: #break is allowed
    std::vector<std::string> open_blocks_;     // keywords of the blocks being evaluated
    const ast::Node* block_item_ = nullptr;    // the block being evaluated as a block's item
    std::vector<uint32_t> rand_streams_;  // seed() streams, indexed by the value seed() returns
    // Parsed trees stay alive for the whole run: MacroValue/FunctionValue point into them.
    std::vector<ast::NodePtr> trees_;
    std::map<std::string, const ast::Node*> file_cache_;
    std::map<const ast::Node*, const ast::Node*> macro_cache_;  // null: no tree as written
    // Trees of bodies parsed with decided conditions, by macro and blanked body text.
    std::map<std::pair<const ast::Node*, std::string>, const ast::Node*> decided_macro_bodies_;
};

}  // namespace lumen::interp

// Building ast::Node trees while the grammar matches. A PEGTL control class (build_control)
// opens a frame when a node-producing rule starts, and on success hands the frame to that
// rule's finisher and appends the result to the enclosing frame; on failure the frame is
// dropped, and nodes appended by a rule that later fails are truncated, so backtracking never
// leaves stray nodes. The same hook counts nesting depth (kMaxNesting).
#pragma once
#include <string_view>
#include <vector>

#include <tao/pegtl.hpp>

#include "parser/ast.hpp"
#include "parser/grammar.hpp"
#include "parser/parser.hpp"

namespace lumen::parser {

using InputIterator = tao::pegtl::internal::iterator;

struct Frame {
    ast::NodePtr node;
    const char* begin = nullptr;  // where the rule started: its matched text is [begin, end)
};

class BuildState;
// Turns a finished frame into the node to append (or nullptr to append nothing).
using Finisher = ast::NodePtr (*)(ast::NodePtr node, std::string_view text, BuildState& st);

class BuildState {
public:
    explicit BuildState(const SourceFile& file);

    SourceLoc loc(const InputIterator& it) const;
    const SourceFile& file() const { return *file_; }

    void open(ast::Kind kind, const InputIterator& at);
    void close(Finisher finish, const char* end);
    // Drops the innermost frame; its node is kept for the next open (every item tries several
    // rules, so most opened nodes are dropped).
    void discard() {
        ast::NodePtr node = std::move(frames_.back().node);
        frames_.pop_back();
        top_ = &frames_.back().node->children;
        node->children.clear();
        node->extra.reset();
        node->text.clear();
        spare_nodes_.push_back(std::move(node));
    }
    // Every rule that may fail marks and truncates: kept to one load through top_.
    std::size_t mark() const { return top_->size(); }
    void truncate(std::size_t mark) {
        if (top_->size() != mark) top_->resize(mark);
    }
    // Moves the children appended since `mark` into a new node and appends its finished form.
    void wrap(ast::Kind kind, const InputIterator& at, std::size_t mark, Finisher finish,
              const char* end);

    void enter(const InputIterator& at);  // throws LumenError beyond kMaxNesting
    void leave() { --depth_; }

    // Records the raw macro body on the innermost (Macro) frame.
    void macro_body(const InputIterator& begin, const InputIterator& end);

    // Open frames, outermost first (for error messages that name the enclosing construct).
    const std::vector<Frame>& frames() const { return frames_; }

    // The single node built under the root frame.
    ast::NodePtr take_result();

    // Literal runs (grammar.hpp's literal_run), filled in place: a node is made only for a
    // run that succeeds (every item is tried as one first).
    void open_literals();
    void close_literals(bool ok, const InputIterator& at);  // appends the node if ok
    std::size_t literal_mark() const { return run_->values.size(); }
    void literal_truncate(std::size_t mark) { run_->values.resize(mark); }
    // Appends the float written in [begin, end); false (nothing appended) if it is not finite.
    bool literal_value(const char* begin, const char* end);
    // Records the element that started at `at` with the values appended since `mark`: a
    // comma (none), a float (one) or a vector (2 to 5; false for other counts).
    bool literal_element(const InputIterator& at, std::size_t mark);
    bool literal_run_long_enough() const { return run_->value_elements >= ast::kMinLiteralRun; }

    // Long sums and products of literals (grammar.hpp's sum and product chains) are folded
    // while they are read, so that a #declare of millions of terms does not keep a node per
    // number. Operands are folded into the chain's head, left to right as the interpreter
    // evaluates them, once a chain has kFoldedChain operands and while the head and every
    // operand are literal arithmetic (+ - * and / by non-zero) with finite results; the first
    // other operand ends the folding of that chain. Shorter chains keep their nodes.
    static constexpr std::size_t kFoldedChain = 16;
    void begin_chain(std::size_t mark) { chains_.push_back({mark, false, true}); }
    void end_chain() { chains_.pop_back(); }
    void chain_operator_added();  // after each operator of the innermost chain

private:
    const SourceFile* file_;
    std::vector<Frame> frames_;
    std::vector<ast::NodePtr>* top_;  // the innermost frame's children (its node is on the heap)
    int depth_ = 0;
    ast::LiteralRun* run_ = nullptr;  // the open run (spare_run_), else null
    std::shared_ptr<ast::LiteralRun> spare_run_;
    std::vector<ast::NodePtr> spare_nodes_;  // dropped nodes, emptied
    struct Chain {
        std::size_t mark;  // where its operands start in the innermost frame's children
        bool folding;      // long enough, and folded so far
        bool foldable;     // no operand has stopped the folding
    };
    std::vector<Chain> chains_;
};

// ---- finishers (build_ast.cpp) ------------------------------------------------------------

namespace finish {
ast::NodePtr keep(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr text(ast::NodePtr n, std::string_view t, BuildState&);
ast::NodePtr number(ast::NodePtr n, std::string_view t, BuildState&);
ast::NodePtr string(ast::NodePtr n, std::string_view t, BuildState&);
ast::NodePtr member(ast::NodePtr n, std::string_view t, BuildState&);
ast::NodePtr fold_one(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr binary(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr postfix(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr named(ast::NodePtr n, std::string_view, BuildState&);  // text := first token
ast::NodePtr bare_colour(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr array_decl(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr params(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr resolution(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr block(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr branch(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr conditional_block(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr conditionally_opened(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr directive_word(ast::NodePtr n, std::string_view t, BuildState&);
ast::NodePtr declare(ast::NodePtr n, std::string_view t, BuildState&);
ast::NodePtr version(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr for_loop(ast::NodePtr n, std::string_view, BuildState&);
ast::NodePtr macro_param(ast::NodePtr n, std::string_view t, BuildState&);
ast::NodePtr macro(ast::NodePtr n, std::string_view, BuildState&);
}  // namespace finish

// ---- which rules build which nodes ----------------------------------------------------------

// The rules of a literal run, which fill its ast::LiteralRun instead of building nodes.
enum class LiteralRole { None, Run, Vector, Number, Comma, Component };
template <typename Rule>
struct literal_traits {
    static constexpr LiteralRole role = LiteralRole::None;
};
#define LUMEN_LITERAL(rule, r)                   \
    template <>                                  \
    struct literal_traits<rules::rule> {         \
        static constexpr LiteralRole role = r;   \
    }
LUMEN_LITERAL(literal_run, LiteralRole::Run);
LUMEN_LITERAL(run_vector, LiteralRole::Vector);
LUMEN_LITERAL(run_number, LiteralRole::Number);
LUMEN_LITERAL(run_comma, LiteralRole::Comma);
LUMEN_LITERAL(run_component, LiteralRole::Component);
#undef LUMEN_LITERAL

// The chains whose literal operands are folded (BuildState::chain_operator_added), and their
// operators.
template <typename Rule> inline constexpr bool folds_literals = false;
template <> inline constexpr bool folds_literals<rules::sum> = true;
template <> inline constexpr bool folds_literals<rules::product> = true;
template <typename Rule> inline constexpr bool chain_operator = false;
template <> inline constexpr bool chain_operator<rules::add_op> = true;
template <> inline constexpr bool chain_operator<rules::mul_op> = true;

// Default: a rule builds nothing and does not nest.
template <typename Rule>
struct node_traits {
    static constexpr bool builds = false;
    static constexpr bool folds = false;
    static constexpr bool nests = false;
};
template <ast::Kind K, Finisher F = finish::keep, bool Nests = false>
struct makes {
    static constexpr bool builds = true;
    static constexpr bool folds = false;
    static constexpr bool nests = Nests;
    static constexpr ast::Kind kind = K;
    static constexpr Finisher finisher = F;
};
// A rule whose node is only made when it matched more than one child (operator chains,
// postfix suffixes, ternaries): a lone operand is passed through without allocating.
template <ast::Kind K, Finisher F>
struct folding : makes<K, F> {
    static constexpr bool builds = false;
    static constexpr bool folds = true;
};
// A temporary node consumed by its parent's finisher (operator, name, suffix, ...).
template <Finisher F = finish::text, bool Nests = false>
using token = makes<ast::Kind::Null, F, Nests>;
struct nests_only {
    static constexpr bool builds = false;
    static constexpr bool folds = false;
    static constexpr bool nests = true;
};

namespace r = rules;
using K = ast::Kind;
#define LUMEN_NODE(rule, ...) \
    template <>               \
    struct node_traits<r::rule> : __VA_ARGS__ {}

// expressions
LUMEN_NODE(number, makes<K::Number, finish::number>);
LUMEN_NODE(signed_literal, makes<K::Number, finish::number>);
LUMEN_NODE(string_literal, makes<K::String, finish::string>);
LUMEN_NODE(ident, makes<K::Ident, finish::text>);
LUMEN_NODE(spline_type_arg, makes<K::Ident, finish::text>);  // read by a spline call
LUMEN_NODE(paren, nests_only);
LUMEN_NODE(vector, makes<K::Vector, finish::keep, true>);
LUMEN_NODE(call_name, token<>);
LUMEN_NODE(call, makes<K::Call, finish::named, true>);
LUMEN_NODE(rgb_word, token<>);
LUMEN_NODE(component_word, token<>);
LUMEN_NODE(rgb_part, makes<K::ColourPart, finish::named, true>);
LUMEN_NODE(component_part, makes<K::ColourPart, finish::named, true>);
LUMEN_NODE(bare_part, makes<K::ColourPart, finish::bare_colour, true>);
LUMEN_NODE(colour_expr, makes<K::Colour>);
LUMEN_NODE(array_dim, token<finish::keep, true>);
LUMEN_NODE(array_decl, makes<K::ArrayDecl, finish::array_decl>);
LUMEN_NODE(array_init, makes<K::ArrayInit, finish::keep, true>);
LUMEN_NODE(member_suffix, token<finish::member>);
LUMEN_NODE(index_suffix, makes<K::Index, finish::keep, true>);
LUMEN_NODE(postfix, folding<K::Null, finish::postfix>);
LUMEN_NODE(unary_op, token<>);
LUMEN_NODE(prefixed, makes<K::Unary, finish::named, true>);
LUMEN_NODE(mul_op, token<>);
LUMEN_NODE(add_op, token<>);
LUMEN_NODE(cmp_op, token<>);
LUMEN_NODE(and_op, token<>);
LUMEN_NODE(or_op, token<>);
LUMEN_NODE(product, folding<K::Binary, finish::binary>);
LUMEN_NODE(sum, folding<K::Binary, finish::binary>);
LUMEN_NODE(comparison, folding<K::Binary, finish::binary>);
template <bool Cmp>
struct node_traits<r::conjunction<Cmp>> : folding<K::Binary, finish::binary> {};
template <bool Cmp>
struct node_traits<r::disjunction<Cmp>> : folding<K::Binary, finish::binary> {};
template <bool Cmp>
struct node_traits<r::ternary_t<Cmp>> : folding<K::Ternary, finish::fold_one> {};
template <bool Cmp>
struct node_traits<r::ternary_tail<Cmp>> : nests_only {};

// items
LUMEN_NODE(body, makes<K::Body, finish::keep, true>);
LUMEN_NODE(block_word, token<>);
LUMEN_NODE(param_name, token<>);
LUMEN_NODE(block_params, token<finish::params>);
LUMEN_NODE(function_resolution, token<finish::resolution>);
LUMEN_NODE(block, makes<K::Block, finish::block, true>);
LUMEN_NODE(map_entry, makes<K::MapEntry, finish::keep, true>);
LUMEN_NODE(keyword_item, makes<K::Keyword, finish::text>);
LUMEN_NODE(comma_item, makes<K::Comma>);
LUMEN_NODE(semicolon_item, makes<K::Semicolon>);
LUMEN_NODE(poly_term, makes<K::PolyTerm>);
LUMEN_NODE(pwr_term, makes<K::PwrTerm>);

// directives
LUMEN_NODE(unofficial_version, token<>);
LUMEN_NODE(version_directive, makes<K::Version, finish::version>);
LUMEN_NODE(include_directive, makes<K::Include>);
LUMEN_NODE(declare_name, makes<K::Ident, finish::text>);
LUMEN_NODE(declare_target, folding<K::Null, finish::postfix>);
LUMEN_NODE(deprecation, token<finish::keep>);
LUMEN_NODE(declare_directive, makes<K::Declare, finish::declare>);
LUMEN_NODE(undef_name, token<>);
LUMEN_NODE(undef_directive, makes<K::Undef, finish::named>);
LUMEN_NODE(then_branch, makes<K::Branch, finish::branch>);
LUMEN_NODE(elseif_branch, makes<K::Branch, finish::branch>);
LUMEN_NODE(else_branch, makes<K::Branch, finish::branch>);
LUMEN_NODE(if_directive, makes<K::If>);
LUMEN_NODE(conditional_word, token<>);
LUMEN_NODE(conditional_block, makes<K::If, finish::conditional_block, true>);
LUMEN_NODE(conditional_close, token<>);
LUMEN_NODE(conditionally_opened, makes<K::If, finish::conditionally_opened, true>);
LUMEN_NODE(ifdef_name, makes<K::Ident, finish::text>);
LUMEN_NODE(ifdef_target, folding<K::Null, finish::postfix>);
LUMEN_NODE(ifdef_then, makes<K::Branch, finish::branch>);
LUMEN_NODE(ifdef_directive, makes<K::Ifdef, finish::directive_word>);
LUMEN_NODE(case_clause, makes<K::Case>);
LUMEN_NODE(range_clause, makes<K::Range>);
LUMEN_NODE(switch_directive, makes<K::Switch>);
LUMEN_NODE(break_directive, makes<K::Break>);
LUMEN_NODE(while_directive, makes<K::While>);
LUMEN_NODE(for_variable, token<>);
LUMEN_NODE(for_directive, makes<K::For, finish::for_loop>);
LUMEN_NODE(macro_name, token<>);
LUMEN_NODE(macro_param, token<finish::macro_param>);
LUMEN_NODE(macro_directive, makes<K::Macro, finish::macro>);
LUMEN_NODE(default_directive, makes<K::Default, finish::keep, true>);
LUMEN_NODE(message_directive, makes<K::Message, finish::directive_word>);
LUMEN_NODE(file_handle, makes<K::Ident, finish::text>);
LUMEN_NODE(open_mode, makes<K::Ident, finish::text>);
LUMEN_NODE(fileio, makes<K::FileIO, finish::directive_word>);

// entry points
LUMEN_NODE(file, makes<K::Body>);
LUMEN_NODE(fragment, makes<K::Body>);
#undef LUMEN_NODE

}  // namespace lumen::parser

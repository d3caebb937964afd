// The PEGTL control class for the SDL grammar: builds the tree (build_ast.hpp), guards the
// nesting depth, and turns must<> failures into LumenError with the messages of errors.hpp.
#pragma once
#include <tao/pegtl.hpp>

#include "parser/build_ast.hpp"
#include "parser/errors.hpp"

namespace lumen::parser {

template <typename Rule>
struct build_control : tao::pegtl::normal<Rule> {
    template <tao::pegtl::apply_mode A, tao::pegtl::rewind_mode M,
              template <typename...> class Action, template <typename...> class Control,
              typename ParseInput>
    static bool match(ParseInput& in, BuildState& st) {
        using base = tao::pegtl::normal<Rule>;
        using traits = node_traits<Rule>;
        // Lookaheads (at<>, not_at<>) run without actions: build nothing there.
        if constexpr (A == tao::pegtl::apply_mode::nothing) {
            return base::template match<A, M, Action, Control>(in, st);
        } else if constexpr (literal_traits<Rule>::role != LiteralRole::None) {
            return match_literal<A, M, Action, Control>(in, st);
        } else {
            if constexpr (traits::nests) st.enter(in.iterator());
            bool ok;
            if constexpr (traits::folds) {
                const InputIterator at = in.iterator();
                const std::size_t mark = st.mark();
                if constexpr (folds_literals<Rule>) st.begin_chain(mark);
                ok = base::template match<A, M, Action, Control>(in, st);
                if constexpr (folds_literals<Rule>) st.end_chain();
                if (!ok) st.truncate(mark);
                else if (st.mark() > mark + 1) st.wrap(traits::kind, at, mark, traits::finisher, in.current());
            } else if constexpr (traits::builds) {
                st.open(traits::kind, in.iterator());
                ok = base::template match<A, M, Action, Control>(in, st);
                if (ok) st.close(traits::finisher, in.current());
                else st.discard();
                if constexpr (chain_operator<Rule>)
                    if (ok) st.chain_operator_added();
            } else {
                const std::size_t mark = st.mark();
                ok = base::template match<A, M, Action, Control>(in, st);
                if (!ok) st.truncate(mark);
            }
            if constexpr (traits::nests) st.leave();
            return ok;
        }
    }

    // A literal run's rules fill the run; each may still fail after matching (a value that
    // overflows, a vector of 6, a run too short), so each rewinds its input itself.
    template <tao::pegtl::apply_mode A, tao::pegtl::rewind_mode M,
              template <typename...> class Action, template <typename...> class Control,
              typename ParseInput>
    static bool match_literal(ParseInput& in, BuildState& st) {
        using base = tao::pegtl::normal<Rule>;
        constexpr LiteralRole role = literal_traits<Rule>::role;
        auto m = in.template mark<M>();
        constexpr auto next = decltype(m)::next_rewind_mode;
        const InputIterator at = in.iterator();
        if constexpr (role == LiteralRole::Run) {
            st.open_literals();
            const bool ok = base::template match<A, next, Action, Control>(in, st) &&
                            st.literal_run_long_enough();
            st.close_literals(ok, at);
            return m(ok);
        } else {
            const std::size_t mark = st.literal_mark();
            bool ok = base::template match<A, next, Action, Control>(in, st);
            if constexpr (role == LiteralRole::Component)
                ok = ok && st.literal_value(at.data, in.current());
            else if constexpr (role == LiteralRole::Number)
                ok = ok && st.literal_value(at.data, in.current()) && st.literal_element(at, mark);
            else
                ok = ok && st.literal_element(at, mark);
            if (!ok) st.literal_truncate(mark);
            return m(ok);
        }
    }

    template <typename ParseInput, typename... States>
    [[noreturn]] static void raise(const ParseInput& in, BuildState& st) {
        std::string hint;
        std::string msg = error_text<Rule>(in, st, hint);
        throw LumenError(st.loc(in.iterator()), msg, hint);
    }
};

}  // namespace lumen::parser

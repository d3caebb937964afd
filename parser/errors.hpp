// What each must<> point of the grammar says when it fails (PEGTL's error_message pattern, as
// in must_if), plus messages that name the enclosing construct ("expected '}' to close
// 'sphere' block opened at 3:1", "missing #end for #if at 4:1").
#pragma once
#include <string>

#include "parser/build_ast.hpp"
#include "base/diagnostics.hpp"
#include "parser/grammar.hpp"

namespace lumen::parser {

template <typename Rule>
inline constexpr const char* error_message = nullptr;

#define LUMEN_ERROR(rule, text) \
    template <>                 \
    inline constexpr const char* error_message<rules::rule> = text

LUMEN_ERROR(expression, "expected expression");
LUMEN_ERROR(plain_expression, "expected expression");
LUMEN_ERROR(vector_component, "expected vector component");
LUMEN_ERROR(close_paren, "expected ')'");
LUMEN_ERROR(open_paren, "expected '('");
LUMEN_ERROR(close_angle, "expected '>' to close vector");
LUMEN_ERROR(close_bracket, "expected ']'");
LUMEN_ERROR(open_brace, "expected '{'");
LUMEN_ERROR(colon, "expected ':' in conditional expression");
LUMEN_ERROR(comma, "expected ','");
LUMEN_ERROR(unary, "expected expression after unary operator");
LUMEN_ERROR(product, "expected expression after operator");
LUMEN_ERROR(sum, "expected expression after operator");
LUMEN_ERROR(call_arg, "expected argument");
LUMEN_ERROR(colour_first_part, "expected colour value after 'color'");
LUMEN_ERROR(equals_sign, "expected '=' after the declared name");
LUMEN_ERROR(declare_rhs, "expected value after '='");
LUMEN_ERROR(declare_target, "expected identifier to declare");
LUMEN_ERROR(undef_name, "expected identifier after #undef");
LUMEN_ERROR(ifdef_target, "expected identifier");
LUMEN_ERROR(version_value, "expected version number");
LUMEN_ERROR(for_variable, "expected loop variable name");
LUMEN_ERROR(macro_name, "expected macro name");
LUMEN_ERROR(macro_param, "expected macro parameter name");
LUMEN_ERROR(file_handle, "expected file identifier");
LUMEN_ERROR(open_mode, "expected 'read', 'write' or 'append'");
LUMEN_ERROR(unterminated_comment, "unterminated comment");
LUMEN_ERROR(unterminated_string, "unterminated string");
LUMEN_ERROR(string_literal, "expected string");
#undef LUMEN_ERROR
template <bool Cmp>
inline constexpr const char* error_message<rules::ternary_t<Cmp>> = "expected expression";
template <bool Cmp>
inline constexpr const char* error_message<rules::conjunction<Cmp>> =
    "expected expression after operator";
template <>
inline constexpr const char* error_message<rules::comparison> = "expected expression after operator";

// ---- building messages ------------------------------------------------------------------

namespace detail {

// "'word'", "'}'" or "end of file": what the input holds at the error position.
std::string describe_next(const char* p, const char* end);
// Position of the innermost open frame of one of `kinds`, or null.
const Frame* innermost(const BuildState& st, std::initializer_list<ast::Kind> kinds);
// "3:1"
std::string line_col(const SourceLoc& loc);
// The name a directive frame was opened with ("if", "while", ...).
std::string directive_name(const Frame& f);

std::string close_brace_message(const BuildState& st, const char* p, const char* end);
std::string close_bracket_message(const BuildState& st);
std::string end_directive_message(const BuildState& st, bool at_eof);
std::string end_of_file_message(const char* p, const char* end, std::string& hint);
std::string unknown_directive_message(const char* p, const char* end, std::string& hint);
std::string reserved_name_message(const char* p, const char* end);

}  // namespace detail

// The message for a failed must<Rule>; `hint` may be filled with a suggestion.
template <typename Rule, typename ParseInput>
std::string error_text(const ParseInput& in, const BuildState& st, std::string& hint) {
    const char* p = in.current();
    const char* end = in.end();
    namespace r = rules;
    if constexpr (std::is_same_v<Rule, r::close_brace>) {
        return detail::close_brace_message(st, p, end);
    } else if constexpr (std::is_same_v<Rule, r::close_bracket>) {
        return detail::close_bracket_message(st) + ", found " + detail::describe_next(p, end);
    } else if constexpr (std::is_same_v<Rule, r::end_directive> ||
                         std::is_same_v<Rule, r::missing_macro_end>) {
        return detail::end_directive_message(st, p == end);
    } else if constexpr (std::is_same_v<Rule, r::end_of_file>) {
        return detail::end_of_file_message(p, end, hint);
    } else if constexpr (std::is_same_v<Rule, r::unknown_directive>) {
        return detail::unknown_directive_message(p, end, hint);
    } else if constexpr (std::is_same_v<Rule, r::reserved_declare_name>) {
        return detail::reserved_name_message(p, end);
    } else {
        static_assert(error_message<Rule> != nullptr, "a must<> point has no error message");
        std::string msg = error_message<Rule>;
        if (msg.rfind("expected", 0) == 0) msg += ", found " + detail::describe_next(p, end);
        return msg;
    }
}

}  // namespace lumen::parser

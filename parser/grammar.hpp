// The SDL grammar as PEGTL rules. Rules only: what each rule builds is in build_ast.hpp, and
// what a failed must<> point says is in errors.hpp.
//
// Padding convention: a rule consumes no leading whitespace, and item-level rules consume the
// whitespace and comments after themselves (`sep`), so a node's location is its first
// character.
#pragma once
#include <cctype>
#include <cstring>
#include <string_view>

#include <tao/pegtl.hpp>

#include "parser/keywords.hpp"

namespace lumen::parser::rules {

namespace pegtl = tao::pegtl;
using namespace tao::pegtl;

// ---- lexical --------------------------------------------------------------------------------

// Length of the identifier at the input (0 if none): [A-Za-z_][A-Za-z0-9_]*.
template <typename ParseInput>
std::size_t word_length(ParseInput& in) {
    const std::size_t avail = in.size(256);
    const char* p = in.current();
    auto first = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    auto other = [&](char c) { return first(c) || (c >= '0' && c <= '9'); };
    if (avail == 0 || !first(p[0])) return 0;
    std::size_t n = 1;
    while (n < avail && other(p[n])) ++n;
    return n;
}

// A whole identifier-like word accepted by `Pred` (a keyword class from keywords.hpp).
template <bool (*Pred)(std::string_view)>
struct word_if {
    using rule_t = word_if;
    using subs_t = empty_list;
    template <typename ParseInput>
    static bool match(ParseInput& in) {
        const std::size_t n = word_length(in);
        if (n == 0 || !Pred(std::string_view(in.current(), n))) return false;
        in.bump_in_this_line(n);
        return true;
    }
};

inline bool any_word(std::string_view) { return true; }
inline bool user_or_expression_word(std::string_view w) {
    return !is_reserved(w) || is_expression_word(w);
}
inline bool plain_keyword(std::string_view w) {
    return is_reserved(w) && !is_expression_word(w) && w != "array" && !is_colour_keyword(w) &&
           !is_rgb_word(w);
}
inline bool unreserved_word(std::string_view w) { return !is_reserved(w); }
inline bool spline_type_word(std::string_view w) {
    return w == "linear_spline" || w == "quadratic_spline" || w == "cubic_spline" ||
           w == "natural_spline";
}
inline bool reserved_word(std::string_view w) { return is_reserved(w); }

// Scanners shared by the comment/string rules and the raw macro-body scanner. Each takes a
// pointer at the opening delimiter and returns the pointer after the closing one, or nullptr
// when the input ends first. Loops, not recursion, so nesting depth is no stack hazard.
inline const char* skip_block_comment(const char* p, const char* end) {
    int depth = 0;
    while (p + 1 < end) {
        if (p[0] == '/' && p[1] == '*') {
            ++depth;
            p += 2;
        } else if (p[0] == '*' && p[1] == '/') {
            p += 2;
            if (--depth == 0) return p;
        } else {
            ++p;
        }
    }
    return nullptr;
}
inline const char* skip_string(const char* p, const char* end) {
    for (++p; p < end; ++p) {
        if (*p == '\\' && p + 1 < end) ++p;
        else if (*p == '"') return p + 1;
    }
    return nullptr;
}

// Error tags (no input is matched by them; errors.hpp gives their messages).
struct unterminated_comment {};
struct unterminated_string {};
struct missing_macro_end {};

// Matches a delimited token with `Skip`; raises `Error` (located at the opening delimiter)
// when the input ends inside it.
template <char C0, char C1, const char* (*Skip)(const char*, const char*), typename Error>
struct delimited {
    using rule_t = delimited;
    using subs_t = empty_list;
    template <apply_mode A, rewind_mode M, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename... States>
    static bool match(ParseInput& in, States&&... st) {
        if (in.empty() || in.peek_char(0) != C0) return false;
        if (C1 != 0 && (in.size(2) < 2 || in.peek_char(1) != C1)) return false;
        const char* after = Skip(in.current(), in.end());
        if (!after) Control<Error>::raise(in, st...);
        in.bump(std::size_t(after - in.current()));
        return true;
    }
};

// block_comment := "/*" (block_comment | any)* "*/"   (comments nest, as in POV-Ray)
struct block_comment : delimited<'/', '*', skip_block_comment, unterminated_comment> {};
// line_comment := "//" any* (eol | eof)
struct line_comment : seq<two<'/'>, until<eolf>> {};
// sep := (space | line_comment | block_comment | ^Z)*
// Most of a file's bytes pass through here (include files are mostly comments and
// indentation), so runs of white space are skipped in one loop, not a rule per byte.
struct sep {
    using rule_t = sep;
    using subs_t = empty_list;
    template <apply_mode A, rewind_mode M, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename... States>
    static bool match(ParseInput& in, States&&... st) {
        for (;;) {
            const char* p = in.current();
            const char* q = p;
            for (const char* e = in.end(); q < e; ++q) {
                const char c = *q;
                if (c != ' ' && c != '\n' && c != '\t' && c != '\r' && c != '\v' && c != '\f' &&
                    c != '\x1a')
                    break;
            }
            if (q != p) in.bump(std::size_t(q - p));
            if (in.size(2) < 2 || in.peek_char(0) != '/') return true;
            if (in.peek_char(1) == '/') {  // line_comment: to the end of the line, or of the file
                const void* eol = std::memchr(in.current(), '\n', in.size());
                in.bump(eol ? std::size_t(static_cast<const char*>(eol) - in.current()) + 1 : in.size());
            } else if (in.peek_char(1) == '*')
                (void)Control<block_comment>::template match<A, rewind_mode::dontcare, Action, Control>(in, st...);
            else
                return true;
        }
    }
};

template <typename R>
struct padded : seq<R, sep> {};

// word := [A-Za-z_][A-Za-z0-9_]*
struct word : word_if<any_word> {};

// number := (digit+ ['.' digit*] | '.' digit+) [('e'|'E') ['+'|'-'] digit+]
struct exponent : seq<one<'e', 'E'>, opt<one<'+', '-'>>, plus<digit>> {};
struct number_text : seq<sor<seq<plus<digit>, opt<one<'.'>, star<digit>>>, seq<one<'.'>, plus<digit>>>,
                         opt<exponent>> {};
struct number : number_text {};
// A number with its minus sign, read as one Number where nothing but ',' or '>' follows it in
// a vector: the same value as the unary minus, without the whole expression grammar (the
// lists of big meshes are made of these).
struct signed_literal : seq<opt<one<'-'>>, number_text> {};

// string := '"' ('\\' any | any but '"')* '"'
struct string_literal : delimited<'"', 0, skip_string, unterminated_string> {};

// ---- expressions ----------------------------------------------------------------------------

template <bool Cmp> struct ternary_t;
struct expression;
struct plain_expression;
struct vector_component;

struct comma : one<','> {};
struct list_sep : seq<sep, comma, sep> {};
// Separator of list elements: a comma, or just whitespace (POV lets commas be omitted in
// vectors, argument lists and array initialisers).
struct element_sep : sor<list_sep, sep> {};

struct close_paren : one<')'> {};
struct close_angle : one<'>'> {};
struct close_bracket : one<']'> {};
struct close_brace : one<'}'> {};
struct open_brace : one<'{'> {};
struct colon : one<':'> {};

// paren := '(' expression ')'
struct paren : seq<one<'('>, sep, must<expression>, sep, must<close_paren>> {};

// vector := '<' vector_component {[','] vector_component} [','] '>'   (`< -1 0 0 >` is valid)
struct vector : seq<one<'<'>, sep, must<vector_component>, star<element_sep, vector_component>,
                    opt<list_sep>, sep, must<close_angle>> {};

struct block;
struct array_decl;
struct array_init;

// call_arg := block | array_decl | expression | spline type (`S(t, cubic_spline)`)
struct spline_type_arg : word_if<spline_type_word> {};
struct call_arg : sor<block, array_decl, plain_expression, spline_type_arg> {};
struct call_name : word_if<user_or_expression_word> {};
// call := name '(' [call_arg {[','] call_arg}] ')'
struct call : seq<call_name, sep, one<'('>, sep, opt<call_arg, star<element_sep, call_arg>>,
                  sep, must<close_paren>> {};

// ident := a non-reserved word or a constant (x, pi, clock, true, ...)
struct ident : word_if<user_or_expression_word> {};

// colour_part := rgb_word expression | component_word expression | expression
struct rgb_word : word_if<is_rgb_word> {};
struct component_word : word_if<is_component_word> {};
struct colour_keyword : word_if<is_colour_keyword> {};
struct rgb_part : seq<rgb_word, sep, must<plain_expression>> {};
struct component_part : seq<component_word, sep, must<plain_expression>> {};
struct bare_part : seq<plain_expression> {};
struct colour_first_part : sor<rgb_part, component_part, bare_part> {};
// colour := ('color'|'colour') colour_first_part {component_part} | rgb_part {component_part}
struct colour_expr
    : sor<seq<colour_keyword, sep, must<colour_first_part>, star<sep, component_part>>,
          seq<rgb_part, star<sep, component_part>>> {};

// array_decl := 'array' ['mixed'] {'[' [expression] ']'} [array_init]
struct array_keyword : TAO_PEGTL_KEYWORD("array") {};
struct array_dim : seq<one<'['>, sep, opt<expression>, sep, must<close_bracket>> {};
struct array_decl : seq<array_keyword, sep, opt<TAO_PEGTL_KEYWORD("mixed"), sep>,
                        star<array_dim, sep>, opt<array_init>> {};
// array_init := '{' [element {[','] element} [',']] '}' ; element := array_init | block | expr
struct array_element : sor<array_init, block, plain_expression> {};
struct array_init : seq<one<'{'>, sep, opt<array_element, star<element_sep, array_element>>,
                        opt<list_sep>, sep, must<close_brace>> {};

// primary := number | string | vector | paren | array_decl | colour | call | ident | #if
//   (an #if inside an expression chooses the value: `(#if (M) A #else B #end)`, math.inc)
struct if_directive;
// Rules that build a node are guarded by a lookahead where that is cheap: a lookahead builds
// nothing, and most items and operands are tried against several rules before one matches.
struct primary : sor<seq<at<sor<digit, one<'.'>>>, number>, seq<at<one<'"'>>, string_literal>,
                     seq<at<one<'<'>>, vector>, paren, seq<at<TAO_PEGTL_KEYWORD("array")>, array_decl>,
                     seq<at<sor<colour_keyword, rgb_word>>, colour_expr>,
                     seq<at<call_name, sep, one<'('>>, call>, ident,
                     seq<at<one<'#'>>, if_directive>> {};

// postfix := primary {'.' word | '[' expression ']'}
struct member_suffix : seq<one<'.'>, word> {};
struct index_suffix : seq<one<'['>, sep, must<expression>, sep, must<close_bracket>> {};
// (no whitespace before a suffix, so `[0 Red] [1 Blue]` map entries never read as indexing)
struct postfix : seq<primary, star<sor<member_suffix, seq<at<one<'['>>, index_suffix>>>> {};

// unary := ('-' | '+' | '!') unary | postfix
struct unary_op : one<'-', '+', '!'> {};
struct unary;
struct prefixed : seq<unary_op, sep, must<unary>> {};
struct unary : sor<seq<at<unary_op>, prefixed>, postfix> {};

// Binary levels: operand {op operand}, one flat node per chain.
struct mul_op : one<'*', '/'> {};
struct add_op : one<'+', '-'> {};
struct cmp_op : sor<string<'<', '='>, string<'>', '='>, string<'!', '='>, one<'=', '<', '>'>> {};
struct and_op : one<'&'> {};
struct or_op : one<'|'> {};

template <typename Operand, typename Op>
struct chain : seq<Operand, star<sep, at<Op>, Op, sep, must<Operand>>> {};

struct product : chain<unary, mul_op> {};
struct sum : chain<product, add_op> {};
struct comparison : chain<sum, cmp_op> {};
template <bool Cmp>
using relational = std::conditional_t<Cmp, comparison, sum>;
template <bool Cmp>
struct conjunction : chain<relational<Cmp>, and_op> {};
template <bool Cmp>
struct disjunction : chain<conjunction<Cmp>, or_op> {};
// ternary := disjunction ['?' ternary ':' ternary]
template <bool Cmp>
struct ternary_tail : seq<sep, one<'?'>, sep, must<ternary_t<Cmp>>, sep, must<colon>, sep,
                          must<ternary_t<Cmp>>> {};
template <bool Cmp>
struct ternary_t : seq<disjunction<Cmp>, opt<ternary_tail<Cmp>>> {};

// expression := ternary with comparisons: only inside '(' ')' and '[' ']', as in POV-Ray
struct expression : seq<ternary_t<true>> {};
// plain_expression := ternary without top-level comparisons: everywhere else, so that
// `box { <0,0,0> <1,1,1> }`, `[0 <0,1>]` and `Foo(off <1,2>)` read '<' as a new vector
struct plain_expression : seq<ternary_t<false>> {};
// vector_component := plain_expression ('>' closes the vector)
struct literal_component : seq<signed_literal, at<sep, one<',', '>'>>> {};
struct vector_component : sor<literal_component, plain_expression> {};

// ---- items ----------------------------------------------------------------------------------

struct item;
struct directive;

// body := item*   (a directive branch; stops at '}', ']', '#end', '#else', ... or eof)
struct body : star<item> {};

// block := word ['(' word {',' word} ')'] '{' item* '}'
//          | 'function' expr [','] expr '{' item* '}'     (height_field resolution)
struct block_word : word {};
struct param_name : word {};
struct block_params : seq<one<'('>, sep, opt<param_name, star<list_sep, param_name>>, sep,
                          one<')'>> {};
struct function_resolution : seq<plain_expression, element_sep, plain_expression, sep> {};
struct block_head
    : sor<seq<at<TAO_PEGTL_KEYWORD("function")>, block_word, sep, not_at<one<'(', '{'>>,
              function_resolution>,
          seq<block_word, sep, opt<block_params, sep>>> {};
struct block : seq<block_head, open_brace, sep, star<item>, must<close_brace>> {};

// map_entry := '[' item* ']'
struct map_entry : seq<one<'['>, sep, star<item>, must<close_bracket>> {};

// keyword := a reserved word that is neither an expression word nor a colour word
struct keyword_item : word_if<plain_keyword> {};
struct comma_item : one<','> {};
struct semicolon_item : one<';'> {};

// poly_term := 'xyz' '(' expr ',' expr ',' expr ')' ':' expr   (polynomial { } terms)
struct poly_term : seq<TAO_PEGTL_KEYWORD("xyz"), sep, one<'('>, sep, plain_expression, list_sep,
                       plain_expression, list_sep, plain_expression, sep, one<')'>, sep,
                       one<':'>, sep, plain_expression> {};

// pwr_term := 'pwr' '(' expr ',' expr ')'   (julia_fractal's complex exponent)
struct pwr_term : seq<TAO_PEGTL_KEYWORD("pwr"), sep, one<'('>, sep, plain_expression, list_sep,
                      plain_expression, sep, one<')'>> {};

// literal_run := (run_vector | run_number | ',')+ with at least kMinLiteralRun floats and
// vectors (build_control checks the count): the lists of big meshes, read into one
// ast::LiteralRun. An element is only taken where nothing could make it part of an
// expression: a float or vector followed by ',', '}', ']', '<' or a directive, vector
// components followed by ',' or '>'; anything else ends the run and is read as before.
struct run_number_text : seq<opt<one<'-'>>, number_text> {};
struct run_follow : at<sep, one<',', '}', ']', '<', '#'>> {};
struct run_component : seq<run_number_text, at<sep, one<',', '>'>>> {};
struct run_vector : seq<one<'<'>, sep, run_component, star<element_sep, run_component>,
                        opt<list_sep>, sep, one<'>'>, run_follow> {};
struct run_number : seq<run_number_text, run_follow> {};
struct run_comma : one<','> {};
struct literal_run : plus<sor<run_vector, run_number, run_comma>, sep> {};

// item := directive | literal run | block | map_entry | ',' | ';' | poly_term | pwr_term
//         | keyword | expression
// A vector that no operator follows is an item by itself: tried first, it spares the lists of
// big meshes the whole expression grammar.
struct vector_item : seq<vector, not_at<one<'.', '['>>,
                         not_at<sep, one<'+', '-', '*', '/', '&', '|', '?', '=', '!', '>'>>> {};
struct block_start : seq<word, sep, one<'{', '('>> {};
struct item : sor<seq<at<one<'#'>>, directive>, literal_run, seq<at<one<'<'>>, padded<vector_item>>,
                  seq<at<sor<block_start, TAO_PEGTL_KEYWORD("function")>>, padded<block>>,
                  seq<at<one<'['>>, padded<map_entry>>, seq<at<one<','>>, padded<comma_item>>,
                  seq<at<one<';'>>, padded<semicolon_item>>,
                  seq<at<TAO_PEGTL_KEYWORD("xyz")>, padded<poly_term>>,
                  seq<at<TAO_PEGTL_KEYWORD("pwr")>, padded<pwr_term>>,
                  seq<at<keyword_item>, padded<keyword_item>>,
                  padded<plain_expression>> {};

// ---- directives -----------------------------------------------------------------------------

// hash<W> := '#' blank* W   (W a whole word)
template <typename W>
struct hash : seq<one<'#'>, star<blank>, W> {};
#define LUMEN_DIRECTIVE(name, text) \
    struct name : hash<TAO_PEGTL_KEYWORD(text)> {}

LUMEN_DIRECTIVE(kw_version, "version");
LUMEN_DIRECTIVE(kw_include, "include");
LUMEN_DIRECTIVE(kw_declare, "declare");
LUMEN_DIRECTIVE(kw_local, "local");
LUMEN_DIRECTIVE(kw_undef, "undef");
LUMEN_DIRECTIVE(kw_if, "if");
LUMEN_DIRECTIVE(kw_ifdef, "ifdef");
LUMEN_DIRECTIVE(kw_ifndef, "ifndef");
LUMEN_DIRECTIVE(kw_elseif, "elseif");
LUMEN_DIRECTIVE(kw_else, "else");
LUMEN_DIRECTIVE(kw_end, "end");
LUMEN_DIRECTIVE(kw_switch, "switch");
LUMEN_DIRECTIVE(kw_case, "case");
LUMEN_DIRECTIVE(kw_range, "range");
LUMEN_DIRECTIVE(kw_break, "break");
LUMEN_DIRECTIVE(kw_while, "while");
LUMEN_DIRECTIVE(kw_for, "for");
LUMEN_DIRECTIVE(kw_macro, "macro");
LUMEN_DIRECTIVE(kw_default, "default");
LUMEN_DIRECTIVE(kw_debug, "debug");
LUMEN_DIRECTIVE(kw_warning, "warning");
LUMEN_DIRECTIVE(kw_error, "error");
LUMEN_DIRECTIVE(kw_render, "render");
LUMEN_DIRECTIVE(kw_statistics, "statistics");
LUMEN_DIRECTIVE(kw_fopen, "fopen");
LUMEN_DIRECTIVE(kw_fclose, "fclose");
LUMEN_DIRECTIVE(kw_read, "read");
LUMEN_DIRECTIVE(kw_write, "write");
#undef LUMEN_DIRECTIVE

struct end_directive : padded<kw_end> {};
struct optional_semicolon : opt<one<';'>, sep> {};

// version := '#version' ('unofficial' text-up-to-';' | expression) [';']
struct unofficial_version : seq<TAO_PEGTL_KEYWORD("unofficial"), until<at<one<';'>>>> {};
struct version_value : sor<unofficial_version, plain_expression> {};
struct version_directive : seq<kw_version, sep, must<version_value>, sep, optional_semicolon> {};

// include := '#include' expression
struct include_directive : seq<kw_include, sep, must<plain_expression>, sep> {};

// declare := ('#declare' | '#local') target '=' rhs [';']
//   target := word {'[' expression ']'}   (not a reserved word)
//   rhs := texture-block {texture-block} | block | array_decl | #if/#ifdef/#switch/#include
//        | expression
struct declare_name : word_if<unreserved_word> {};
struct reserved_declare_name : word_if<reserved_word> {};
struct declare_target : seq<declare_name, star<index_suffix>> {};
struct equals_sign : one<'='> {};
struct texture_block : seq<at<TAO_PEGTL_KEYWORD("texture"), sep, one<'{'>>, block> {};
struct switch_directive;
struct ifdef_directive;
struct include_directive;
struct declare_rhs : sor<seq<texture_block, star<sep, texture_block>>, block, array_decl,
                         if_directive, ifdef_directive, switch_directive, include_directive,
                         plain_expression> {};
// deprecated := 'deprecated' ['once'] string   (a warning to print when the name is used)
struct deprecation : seq<TAO_PEGTL_KEYWORD("deprecated"), sep,
                         opt<TAO_PEGTL_KEYWORD("once"), sep>, must<string_literal>> {};
struct declare_directive
    : seq<sor<kw_declare, kw_local>, sep, opt<deprecation, sep>,
          sor<seq<at<reserved_declare_name>, pegtl::raise<reserved_declare_name>>,
              must<declare_target>>,
          sep,
          must<equals_sign>, sep, must<declare_rhs>, sep, optional_semicolon> {};

// undef := '#undef' word
struct undef_name : word {};
struct undef_directive : seq<kw_undef, sep, must<undef_name>, sep> {};

// if := '#if' expression body {'#elseif' expression body} ['#else' body] '#end'
struct then_branch : seq<must<plain_expression>, sep, body> {};
struct elseif_branch : seq<kw_elseif, sep, must<plain_expression>, sep, body> {};
struct else_branch : seq<kw_else, sep, body> {};
struct if_directive
    : seq<kw_if, sep, then_branch, star<elseif_branch>, opt<else_branch>, must<end_directive>> {};

// A block whose keyword is chosen by a condition, closed after the #end (shapes.inc's
// `#if (UseMerge) merge { #else union { #end ... }`). Built as an If whose two branches
// each hold the whole block; the body items are copied into the second branch.
// conditional_block := '#if' expr word '{' '#else' word '{' '#end' item* '}'
struct conditional_word : word {};
struct conditional_block
    : seq<kw_if, sep, plain_expression, sep, conditional_word, sep, one<'{'>, sep, kw_else, sep,
          conditional_word, sep, one<'{'>, sep, end_directive, star<item>,
          must<close_brace>, sep> {};

// A block opened and closed under the same condition (shapes3.inc's
// `#if (A > 180) merge { #end ... #if (A > 180) } #end`). Built as an If whose first branch
// holds the block and whose else branch holds a copy of the bare body items.
// conditionally_opened := '#if' expr word '{' '#end' item* '#if' expr '}' '#end'
// (conditional_close is a lookahead, so it must not parse items: errors inside would escape)
struct conditional_close : seq<kw_if, sep, plain_expression, sep, one<'}'>, sep, kw_end> {};
struct conditionally_opened
    : seq<kw_if, sep, plain_expression, sep, conditional_word, sep, one<'{'>, sep,
          end_directive, star<not_at<conditional_close>, item>, conditional_close, sep> {};

// ifdef := ('#ifdef' | '#ifndef') '(' word {'[' expression ']'} ')' body ['#else' body] '#end'
struct open_paren : one<'('> {};
struct ifdef_name : word {};
struct ifdef_target : seq<ifdef_name, star<index_suffix>> {};
struct ifdef_then : seq<body> {};
struct ifdef_directive : seq<sor<kw_ifdef, kw_ifndef>, sep, must<open_paren>, sep,
                             must<ifdef_target>, sep, must<close_paren>, sep, ifdef_then,
                             opt<else_branch>, must<end_directive>> {};

// switch := '#switch' expression {case | range | else} '#end'
//   case := '#case' expression body ; range := '#range' '(' expr ',' expr ')' body
struct case_clause : seq<kw_case, sep, must<plain_expression>, sep, body> {};
struct range_bounds : seq<must<open_paren>, sep, must<plain_expression>, sep, must<comma>, sep,
                          must<plain_expression>, sep, must<close_paren>> {};
struct range_clause : seq<kw_range, sep, range_bounds, sep, body> {};
struct switch_directive : seq<kw_switch, sep, must<plain_expression>, sep,
                              star<sor<case_clause, range_clause, else_branch>>,
                              must<end_directive>> {};

// break := '#break'
struct break_directive : seq<kw_break, sep> {};

// while := '#while' expression body '#end'
struct while_directive : seq<kw_while, sep, must<plain_expression>, sep, body, must<end_directive>> {};

// for := '#for' '(' word ',' expr ',' expr [',' expr] ')' body '#end'
struct for_variable : word {};
struct for_step : opt<list_sep, must<plain_expression>> {};
struct for_directive
    : seq<kw_for, sep, must<open_paren>, sep, must<for_variable>, sep, must<comma>, sep,
          must<plain_expression>, sep, must<comma>, sep, must<plain_expression>, for_step, sep,
          must<close_paren>, sep, body, must<end_directive>> {};

// macro := '#macro' word '(' [param {',' param}] ')' raw-text '#end'
//   param := ['optional'] word (commas may be omitted, as POV allows); the raw text runs to
//   the matching #end (not parsed here)
struct macro_name : word {};
struct optional_param : seq<TAO_PEGTL_KEYWORD("optional"), sep, word> {};
struct macro_param : sor<optional_param, word> {};
struct macro_params : opt<macro_param, star<sor<list_sep, sep>, macro_param>, opt<list_sep>> {};
// The raw macro body: everything up to the #end matching this #macro, counting nested
// #if/#ifdef/#ifndef/#switch/#while/#for/#macro and skipping comments and strings. The state
// records the byte range (State::macro_body); the body is parsed when the macro is called.
inline bool opens_directive_block(std::string_view w) {
    return w == "if" || w == "ifdef" || w == "ifndef" || w == "switch" || w == "while" ||
           w == "for" || w == "macro";
}
struct macro_raw_body {
    using rule_t = macro_raw_body;
    using subs_t = empty_list;
    template <apply_mode A, rewind_mode M, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput, typename State>
    static bool match(ParseInput& in, State& st) {
        const auto begin = in.iterator();
        const char* p = in.current();
        const char* const end = in.end();
        int depth = 1;
        while (p < end) {
            if (p[0] == '/' && p + 1 < end && p[1] == '/') {
                while (p < end && *p != '\n') ++p;
            } else if (p[0] == '/' && p + 1 < end && p[1] == '*') {
                const char* after = skip_block_comment(p, end);
                if (!after) {
                    in.bump(std::size_t(p - in.current()));
                    Control<unterminated_comment>::raise(in, st);
                }
                p = after;
            } else if (p[0] == '"') {
                const char* after = skip_string(p, end);
                if (!after) {
                    in.bump(std::size_t(p - in.current()));
                    Control<unterminated_string>::raise(in, st);
                }
                p = after;
            } else if (p[0] == '#') {
                const char* q = p + 1;
                while (q < end && (*q == ' ' || *q == '\t')) ++q;
                const char* w = q;
                while (q < end && (std::isalnum(static_cast<unsigned char>(*q)) || *q == '_')) ++q;
                const std::string_view name(w, std::size_t(q - w));
                if (opens_directive_block(name)) {
                    ++depth;
                } else if (name == "end" && --depth == 0) {
                    in.bump(std::size_t(p - in.current()));
                    st.macro_body(begin, in.iterator());
                    return true;
                }
                p = q;
            } else {
                ++p;
            }
        }
        in.bump(std::size_t(end - in.current()));
        Control<missing_macro_end>::raise(in, st);
    }
};
struct macro_directive : seq<kw_macro, sep, must<macro_name>, sep, must<open_paren>, sep,
                             macro_params, sep, must<close_paren>, macro_raw_body,
                             must<end_directive>> {};

// default := '#default' '{' item* '}'
struct default_directive : seq<kw_default, sep, must<open_brace>, sep, star<item>,
                               must<close_brace>, sep> {};

// message := ('#debug' | '#warning' | '#error' | '#render' | '#statistics') expression
struct message_word : sor<kw_debug, kw_warning, kw_error, kw_render, kw_statistics> {};
struct message_directive : seq<message_word, sep, must<plain_expression>, sep> {};

// file_io := '#fopen' word expression word | '#fclose' word
//          | ('#read' | '#write') '(' expression {',' expression} ')'
struct file_handle : word {};
struct open_mode : word {};
// Arguments are read loosely: values, commas (even trailing) and type words (`uint16be`).
struct fileio_args : seq<must<open_paren>, sep,
                         star<sor<padded<comma>, padded<keyword_item>, padded<plain_expression>>>,
                         must<close_paren>> {};
// #write's values may also come from directives among them, as POV-Ray reads a token stream
// (shapes.inc writes a mesh2 with `#write(F, "...", N, #while ... V, #end ")")`).
struct write_args
    : seq<must<open_paren>, sep,
          star<sor<padded<comma>, padded<keyword_item>, seq<at<one<'#'>>, directive>,
                   padded<plain_expression>>>,
          must<close_paren>> {};
struct fileio_directive
    : sor<seq<kw_fopen, sep, must<file_handle>, sep, must<plain_expression>, sep, must<open_mode>>,
          seq<kw_fclose, sep, must<file_handle>>, seq<kw_read, sep, fileio_args>,
          seq<kw_write, sep, write_args>> {};
struct fileio : seq<fileio_directive, sep> {};

// Words that end a directive body rather than start an item.
struct body_terminator : sor<kw_end, kw_else, kw_elseif, kw_case, kw_range> {};
struct unknown_directive : seq<one<'#'>, star<blank>, opt<word>> {};
// A '#' not followed by a word is ignored, as POV-Ray does (`look_at <0,2,0>#`).
struct lone_hash : seq<one<'#'>, not_at<star<blank>, identifier_first>, sep> {};

// directive := one of the above; an unknown '#word' is an error
struct directive
    : sor<declare_directive, conditional_block, conditionally_opened, if_directive,
          while_directive, for_directive, macro_directive,
          ifdef_directive, switch_directive, break_directive, include_directive,
          version_directive, undef_directive, default_directive, message_directive, fileio,
          lone_hash, seq<at<one<'#'>>, not_at<body_terminator>, pegtl::raise<unknown_directive>>> {};

// ---- entry points ---------------------------------------------------------------------------

struct byte_order_mark : TAO_PEGTL_STRING("\xEF\xBB\xBF") {};
struct end_of_file : eof {};
// file := [BOM] sep item* eof
struct file : seq<opt<byte_order_mark>, sep, star<item>, must<end_of_file>> {};
// fragment := sep item* eof   (a macro body)
struct fragment : seq<sep, star<item>, must<end_of_file>> {};
// single_expression := sep expression eof
struct single_expression : seq<sep, must<expression>, sep, must<end_of_file>> {};

}  // namespace lumen::parser::rules

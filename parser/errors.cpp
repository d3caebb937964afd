// Context-dependent parse error messages (see errors.hpp).
#include "parser/errors.hpp"

#include "parser/keywords.hpp"

namespace lumen::parser::detail {

namespace {

bool word_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

std::string_view word_at(const char* p, const char* end) {
    const char* q = p;
    while (q < end && word_char(*q)) ++q;
    return std::string_view(p, std::size_t(q - p));
}

// Concatenation by appending (GCC 12 warns falsely, -Wrestrict, on `"lit" + std::string`).
std::string cat(std::initializer_list<std::string_view> parts) {
    std::string out;
    for (std::string_view p : parts) out.append(p);
    return out;
}

// The word after '#' and blanks at p (p at '#').
std::string_view directive_at(const char* p, const char* end) {
    ++p;
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    return word_at(p, end);
}

}  // namespace

std::string describe_next(const char* p, const char* end) {
    if (p >= end) return "end of file";
    if (*p == '#') return cat({"'#", directive_at(p, end), "'"});
    std::string_view w = word_at(p, end);
    if (!w.empty()) return cat({"'", w.substr(0, 40), "'"});
    if (static_cast<unsigned char>(*p) < 0x20) return "a control character";
    return cat({"'", std::string_view(p, 1), "'"});
}

const Frame* innermost(const BuildState& st, std::initializer_list<ast::Kind> kinds) {
    const auto& frames = st.frames();
    for (auto it = frames.rbegin(); it != frames.rend(); ++it)
        for (ast::Kind k : kinds)
            if (it->node->kind == k) return &*it;
    return nullptr;
}

std::string line_col(const SourceLoc& loc) {
    return std::to_string(loc.line) + ":" + std::to_string(loc.column);
}

std::string directive_name(const Frame& f) {
    return std::string(directive_at(f.begin, f.begin + 64));
}

std::string close_brace_message(const BuildState& st, const char* p, const char* end) {
    using K = ast::Kind;
    const Frame* f = innermost(st, {K::Block, K::Default, K::ArrayInit});
    std::string what = "expected '}'";
    if (f) {
        const ast::Node& n = *f->node;
        if (n.kind == K::Block && !n.children.empty())
            what += " to close '" + n.children.front()->text + "' block";
        else if (n.kind == K::Default)
            what += " to close #default";
        else
            what += " to close array initialiser";
        what += " opened at " + line_col(n.loc);
    }
    return what + ", found " + describe_next(p, end);
}

std::string close_bracket_message(const BuildState& st) {
    const Frame* f = innermost(st, {ast::Kind::MapEntry, ast::Kind::Index, ast::Kind::Null});
    if (f && f->node->kind == ast::Kind::MapEntry)
        return "expected ']' to close map entry opened at " + line_col(f->node->loc);
    return "expected ']'";
}

std::string end_directive_message(const BuildState& st, bool at_eof) {
    using K = ast::Kind;
    const Frame* f = innermost(st, {K::If, K::Ifdef, K::Switch, K::While, K::For, K::Macro});
    if (!f) return "expected #end";
    return cat({at_eof ? "missing" : "expected", " #end for #", directive_name(*f), " at ",
                line_col(f->node->loc)});
}

std::string end_of_file_message(const char* p, const char* end, std::string& hint) {
    if (p < end && *p == '#') {
        std::string_view d = directive_at(p, end);
        if (d == "end") return "#end without matching directive";
        if (d == "else" || d == "elseif") return cat({"#", d, " without matching #if"});
        if (d == "case" || d == "range") return cat({"#", d, " outside #switch"});
    }
    if (p < end && (*p == '}' || *p == ']' || *p == ')' || *p == '>'))
        return cat({"unmatched '", std::string_view(p, 1), "'"});
    (void)hint;
    return "unexpected " + describe_next(p, end);
}

std::string unknown_directive_message(const char* p, const char* end, std::string& hint) {
    std::string d(directive_at(p, end));
    static const std::vector<std::string> directives = {
        "version", "include", "declare", "local", "undef", "ifdef", "ifndef", "if", "elseif",
        "else", "end", "switch", "case", "range", "break", "while", "for", "macro", "default",
        "debug", "warning", "error", "render", "statistics", "fopen", "fclose", "read", "write"};
    hint = did_you_mean(d, directives);
    if (d.empty()) return "expected directive name after '#'";
    return "unknown directive '#" + d + "'";
}

std::string reserved_name_message(const char* p, const char* end) {
    return "cannot declare '" + std::string(word_at(p, end)) + "': it is a reserved word";
}

}  // namespace lumen::parser::detail

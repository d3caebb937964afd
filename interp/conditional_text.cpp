// Scanning a macro body's text for #if groups and blanking the branches decided at its call
// (see conditional_text.hpp).
#include "interp/conditional_text.hpp"

#include <algorithm>
#include <cctype>

namespace lumen::interp {

namespace {

bool identifier_first(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The end of a string or comment starting at p, or p itself when none starts there.
size_t skip_literal(std::string_view t, size_t p, size_t end) {
    if (t[p] == '"') {
        for (++p; p < end && t[p] != '"'; ++p)
            if (t[p] == '\\' && p + 1 < end) ++p;
        return std::min(p + 1, end);
    }
    if (t[p] != '/' || p + 1 >= end) return p;
    if (t[p + 1] == '/') {
        while (p < end && t[p] != '\n') ++p;
        return p;
    }
    if (t[p + 1] != '*') return p;
    int depth = 0;
    while (p + 1 < end) {
        if (t[p] == '/' && t[p + 1] == '*') {
            ++depth;
            p += 2;
        } else if (t[p] == '*' && t[p + 1] == '/') {
            p += 2;
            if (--depth == 0) return p;
        } else {
            ++p;
        }
    }
    return end;
}

size_t skip_space(std::string_view t, size_t p, size_t end) {
    while (p < end) {
        if (std::isspace(static_cast<unsigned char>(t[p]))) {
            ++p;
            continue;
        }
        const size_t q = t[p] == '"' ? p : skip_literal(t, p, end);
        if (q == p) break;
        p = q;
    }
    return p;
}

size_t identifier_end(std::string_view t, size_t p, size_t end) {
    if (p >= end || !identifier_first(t[p])) return p;
    while (p < end && identifier_char(t[p])) ++p;
    return p;
}

// The position after the ')' matching the '(' at p, or nothing.
std::optional<size_t> matching_paren(std::string_view t, size_t p, size_t end) {
    int depth = 0;
    while (p < end) {
        const size_t q = skip_literal(t, p, end);
        if (q != p) {
            p = q;
            continue;
        }
        if (t[p] == '(') ++depth;
        if (t[p] == ')' && --depth == 0) return p + 1;
        ++p;
    }
    return std::nullopt;
}

struct Open {
    bool is_if = false;  // #if; otherwise #ifdef/#ifndef/#while/#for/#switch/#macro
    ConditionalGroup group;
};

// Reads a branch head's condition after its word: one parenthesised expression.
void read_condition(std::string_view t, size_t after_word, size_t end, ConditionalGroup& group,
                    ConditionalBranch& branch) {
    const size_t p = skip_space(t, after_word, end);
    const auto close = p < end && t[p] == '(' ? matching_paren(t, p, end) : std::nullopt;
    if (!close) {
        group.decidable = false;
        branch.cond_begin = branch.head_end = uint32_t(after_word);
        return;
    }
    branch.cond_begin = uint32_t(p);
    branch.head_end = uint32_t(*close);
}

void blank(std::string& s, uint32_t begin, uint32_t end) {
    for (uint32_t i = begin; i < end; ++i)
        if (s[i] != '\n' && s[i] != '\r') s[i] = ' ';
}

}  // namespace

ConditionalScan scan_conditionals(std::string_view t, uint32_t begin, uint32_t end) {
    ConditionalScan scan;
    std::vector<Open> stack;
    size_t p = begin;
    while (p < end) {
        const size_t q = skip_literal(t, p, end);
        if (q != p) {
            p = q;
            continue;
        }
        if (t[p] != '#') {
            ++p;
            continue;
        }
        const size_t hash = p;
        size_t w = p + 1;
        while (w < end && (t[w] == ' ' || t[w] == '\t')) ++w;
        const size_t word_end = identifier_end(t, w, end);
        const std::string_view word = t.substr(w, word_end - w);
        p = std::max(word_end, hash + 1);
        Open* top = stack.empty() ? nullptr : &stack.back();
        const bool in_if = top && top->is_if;
        if (word == "if") {
            Open open{true, {}};
            ConditionalBranch branch{uint32_t(hash), 0, 0, 0};
            read_condition(t, word_end, end, open.group, branch);
            open.group.branches.push_back(branch);
            stack.push_back(std::move(open));
            p = branch.head_end;
        } else if (word == "ifdef" || word == "ifndef" || word == "while" || word == "for" ||
                   word == "switch" || word == "macro") {
            stack.push_back(Open{});
        } else if ((word == "elseif" || word == "else") && in_if) {
            ConditionalGroup& g = top->group;
            g.branches.back().body_end = uint32_t(hash);
            ConditionalBranch branch{uint32_t(hash), uint32_t(word_end), uint32_t(word_end), 0};
            if (word == "elseif") read_condition(t, word_end, end, g, branch);
            g.branches.push_back(branch);
            p = branch.head_end;
        } else if (word == "end" && top) {
            if (in_if) {
                ConditionalGroup g = std::move(top->group);
                g.branches.back().body_end = uint32_t(hash);
                g.end_begin = uint32_t(hash);
                g.end_end = uint32_t(word_end);
                scan.groups.push_back(std::move(g));
            }
            stack.pop_back();
        } else if (word == "declare" || word == "local") {
            const size_t n = skip_space(t, word_end, end);
            const size_t n_end = identifier_end(t, n, end);
            if (n_end > n) scan.assigned.insert(std::string(t.substr(n, n_end - n)));
        }
    }
    std::sort(scan.groups.begin(), scan.groups.end(), [](const auto& a, const auto& b) {
        return a.branches.front().head_begin < b.branches.front().head_begin;
    });
    return scan;
}

std::vector<std::string> condition_identifiers(std::string_view t) {
    std::vector<std::string> names;
    size_t p = 0;
    while (p < t.size()) {
        const size_t q = skip_literal(t, p, t.size());
        if (q != p) {
            p = q;
            continue;
        }
        const size_t e = identifier_end(t, p, t.size());
        if (e == p) {
            // A number's exponent or digits are not names; neither is a member after '.'.
            const bool skip_word = std::isdigit(static_cast<unsigned char>(t[p])) || t[p] == '.';
            ++p;
            if (skip_word)
                while (p < t.size() && identifier_char(t[p])) ++p;
            continue;
        }
        names.emplace_back(t.substr(p, e - p));
        p = e;
    }
    return names;
}

std::optional<std::string> blank_decided_conditionals(std::string_view text,
                                                      const ConditionalScan& scan,
                                                      const DecideCondition& decide) {
    std::string out(text);
    bool decided_any = false;
    std::vector<std::pair<uint32_t, uint32_t>> dropped;  // bodies blanked out
    for (const ConditionalGroup& g : scan.groups) {
        const uint32_t start = g.branches.front().head_begin;
        const bool inside_dropped = std::any_of(dropped.begin(), dropped.end(), [&](const auto& r) {
            return start >= r.first && start < r.second;
        });
        if (inside_dropped || !g.decidable) continue;
        std::optional<size_t> taken;
        bool undecided = false;
        for (size_t i = 0; i < g.branches.size() && !taken && !undecided; ++i) {
            const ConditionalBranch& b = g.branches[i];
            if (!b.has_condition()) {
                taken = i;
                break;
            }
            const std::optional<bool> holds = decide(b.cond_begin, b.head_end);
            if (!holds) undecided = true;
            else if (*holds) taken = i;
        }
        if (undecided) continue;
        decided_any = true;
        for (size_t i = 0; i < g.branches.size(); ++i) {
            const ConditionalBranch& b = g.branches[i];
            blank(out, b.head_begin, b.head_end);
            if (taken && *taken == i) continue;
            blank(out, b.head_end, b.body_end);
            dropped.emplace_back(b.head_end, b.body_end);
        }
        blank(out, g.end_begin, g.end_end);
    }
    if (!decided_any) return std::nullopt;
    return out;
}

}  // namespace lumen::interp

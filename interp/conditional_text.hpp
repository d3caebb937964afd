// Conditionals decided before a macro body is parsed. POV-Ray reads SDL as a token stream, so a
// `#write(` or a `mesh2 {` may be opened in one `#if` branch and closed in a later one, as
// shapes.inc's HFCreate_ does:
//     #if (WriteFile) #write(F, "mesh2 {", N, #else mesh2 { N, #end ... #if (WriteFile) ")" ...
// Such a body has no syntax tree. When its conditions cannot change while it runs (nothing in
// the body assigns their variables), the untaken branches and the directive words around the
// taken ones can be blanked out first: what is left is the text POV-Ray would read, and it
// parses. Blanking keeps every other byte, newline and offset, so source locations stay exact.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace lumen::interp {

// One `#if`/`#elseif`/`#else` branch: its directive head [head_begin, head_end) (the word and,
// for #if/#elseif, the parenthesised condition [cond_begin, head_end)) and its body.
struct ConditionalBranch {
    uint32_t head_begin = 0, head_end = 0;
    uint32_t cond_begin = 0;  // == head_end for #else; no condition
    uint32_t body_end = 0;    // the body is [head_end, body_end)
    bool has_condition() const { return cond_begin != head_end; }
};

// An `#if ... #end` group; `decidable` is false when a condition is not one parenthesised
// expression.
struct ConditionalGroup {
    std::vector<ConditionalBranch> branches;
    uint32_t end_begin = 0, end_end = 0;  // the `#end`
    bool decidable = true;
};

struct ConditionalScan {
    std::vector<ConditionalGroup> groups;  // every group at any depth, in order of its `#if`
    std::set<std::string> assigned;        // names after a #declare or #local in the text
};

// Scans bytes [begin, end) of `text` for `#if` groups, skipping strings and comments (block
// comments nest, as in POV-Ray). Unbalanced directives leave the groups found so far.
ConditionalScan scan_conditionals(std::string_view text, uint32_t begin, uint32_t end);

// The identifiers in a condition's text (for the assigned-variable and macro checks).
std::vector<std::string> condition_identifiers(std::string_view condition);

// Decides what it can: for each group not inside a blanked branch, in text order, `decide`
// gets a branch condition's byte range and answers true, false, or nothing (undecidable: the
// group is left as written). Returns a copy of `text` with the untaken branches and the decided
// directives blanked (spaces, newlines kept), or nothing when no group was decided.
using DecideCondition = std::function<std::optional<bool>(uint32_t begin, uint32_t end)>;
std::optional<std::string> blank_decided_conditionals(std::string_view text,
                                                      const ConditionalScan& scan,
                                                      const DecideCondition& decide);

}  // namespace lumen::interp

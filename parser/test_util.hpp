// Helpers shared by the parser tests: parse text and render the tree as an S-expression.
#pragma once
#include <memory>
#include <string>

#include "parser/dump.hpp"
#include "parser/parser.hpp"

namespace lumen::parser::testing {

// Keeps the SourceFile alive as long as the tree (nodes point at it).
struct Parsed {
    std::unique_ptr<SourceFile> file;
    ast::NodePtr root;
};

inline Parsed parse_text(const std::string& text, const std::string& name = "test.pov") {
    auto f = std::make_unique<SourceFile>(SourceFile{name, text});
    ast::NodePtr root = parse_file(*f);
    return {std::move(f), std::move(root)};
}

// The dump of the items of a whole file, without the enclosing "(Body ...)".
inline std::string items(const std::string& text) {
    std::string d = dump(*parse_text(text).root);
    return d.size() > 7 ? d.substr(6, d.size() - 7) : std::string();
}

inline std::string expr(const std::string& text) {
    SourceFile f{"expr", text};
    return dump(*parse_expression(f));
}

// The error message (with "@line:col") for text that must fail, or "no error".
inline std::string error_of(const std::string& text) {
    try {
        parse_text(text);
    } catch (const LumenError& e) {
        return std::string(e.what()) + " @" + std::to_string(e.diag.loc.line) + ":" +
               std::to_string(e.diag.loc.column);
    }
    return "no error";
}

}  // namespace lumen::parser::testing

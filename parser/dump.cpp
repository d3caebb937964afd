#include "parser/dump.hpp"

#include <sstream>

namespace lumen::parser {

namespace {

void write(std::ostringstream& out, const ast::Node& n) {
    using K = ast::Kind;
    out << '(' << ast::kind_name(n.kind);
    if (n.kind == K::Number) out << ' ' << n.number;
    else if (n.kind == K::String) out << " \"" << n.text << '"';
    else if (!n.text.empty()) out << ' ' << n.text;
    if (!n.more().params.empty()) {
        out << " [";
        for (std::size_t i = 0; i < n.more().params.size(); ++i) {
            if (i) out << ' ';
            if (i < n.more().optional_params.size() && n.more().optional_params[i]) out << "optional ";
            out << n.more().params[i];
        }
        out << ']';
    }
    if (n.kind == K::ArrayDecl && n.flag) out << " init";
    if (n.kind == K::Literals) {  // ", " for a comma, "1" for a float, "<1 2 3>" for a vector
        const ast::LiteralRun& run = *n.more().literals;
        for (std::size_t i = 0, at = 0; i < run.sizes.size(); at += run.sizes[i++]) {
            out << ' ';
            if (run.sizes[i] == 0) out << ',';
            else if (run.sizes[i] == 1) out << run.values[at];
            for (std::size_t k = 0; run.sizes[i] > 1 && k < run.sizes[i]; ++k)
                out << (k ? ' ' : '<') << run.values[at + k] << (k + 1 == run.sizes[i] ? ">" : "");
        }
    }
    for (std::size_t i = 0; i < n.children.size(); ++i) {
        if (n.kind == K::Binary && i > 0) out << ' ' << n.more().ops[i - 1];
        out << ' ';
        write(out, *n.children[i]);
    }
    out << ')';
}

}  // namespace

std::string dump(const ast::Node& n) {
    std::ostringstream out;
    write(out, n);
    return out.str();
}

}  // namespace lumen::parser

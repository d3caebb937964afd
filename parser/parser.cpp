// Entry points of the SDL parser: run the grammar over a file, a macro-body fragment or a
// lone expression, building the tree with build_control.
#include "parser/parser.hpp"

#include <tao/pegtl.hpp>

#include "parser/control.hpp"
#include "parser/grammar.hpp"
#include "parser/text_encoding.hpp"

namespace lumen::parser {

namespace pegtl = tao::pegtl;
using Input = pegtl::memory_input<pegtl::tracking_mode::eager, pegtl::eol::lf_crlf, const char*>;

namespace {

template <typename Rule>
ast::NodePtr run(Input& in, const SourceFile& file) {
    BuildState st(file);
    try {
        pegtl::parse<Rule, pegtl::nothing, build_control>(in, st);
    } catch (const pegtl::parse_error& e) {
        // Not expected (every raise goes through build_control), but never let it escape.
        SourceLoc loc{&file, 0, 0, 0};
        if (!e.positions().empty()) {
            const auto& p = e.positions().front();
            loc = SourceLoc{&file, uint32_t(p.line), uint32_t(p.column), uint32_t(p.byte)};
        }
        throw LumenError(loc, std::string(e.message()));
    }
    ast::NodePtr result = st.take_result();
    if (!result) throw LumenError(SourceLoc{&file, 1, 1, 0}, "nothing parsed");
    return result;
}

}  // namespace

ast::NodePtr parse_file(const SourceFile& file) {
    check_sdl_text(file);
    Input in(file.text.data(), file.text.data() + file.text.size(), file.name.c_str());
    return run<rules::file>(in, file);
}

namespace {

template <typename Rule>
ast::NodePtr run_range(const SourceFile& file, uint32_t begin, uint32_t end, SourceLoc start) {
    if (end > file.text.size() || begin > end)
        throw LumenError(start, "macro body outside its file");
    Input in(file.text.data() + begin, file.text.data() + end, file.name.c_str(), begin,
             start.line, start.column);
    return run<Rule>(in, file);
}

}  // namespace

ast::NodePtr parse_fragment(const SourceFile& file, uint32_t begin, uint32_t end, SourceLoc start) {
    return run_range<rules::fragment>(file, begin, end, start);
}

ast::NodePtr parse_expression(const SourceFile& file, uint32_t begin, uint32_t end, SourceLoc start) {
    return run_range<rules::single_expression>(file, begin, end, start);
}

ast::NodePtr parse_expression(const SourceFile& file) {
    Input in(file.text.data(), file.text.data() + file.text.size(), file.name.c_str());
    ast::NodePtr body = run<rules::single_expression>(in, file);
    return body;
}

}  // namespace lumen::parser

// libFuzzer target: the parser must turn any input into a syntax tree or a LumenError, and
// the interpreter (with small limits) into a scene or a LumenError; never crash, hang or
// overflow the stack. Set LUMEN_FUZZ_PARSE_ONLY=1 to fuzz the parser alone (or build with
// -DLUMEN_FUZZ_PARSER_ONLY to link only the parser library).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#ifndef LUMEN_FUZZ_PARSER_ONLY
#include "interp/interpret.hpp"
#endif
#include "base/diagnostics.hpp"
#include "parser/parser.hpp"

namespace {

#ifndef LUMEN_FUZZ_PARSER_ONLY
bool parse_only() {
    static const bool only = std::getenv("LUMEN_FUZZ_PARSE_ONLY") != nullptr;
    return only;
}

lumen::interp::InterpOptions small_limits() {
    lumen::interp::InterpOptions o;
    o.max_loop_iterations = 2000;  // nested loops multiply: keep each one short
    o.max_macro_depth = 40;
    o.max_include_depth = 6;
    return o;
}
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    lumen::SourceManager sources;
    const lumen::SourceFile* file = sources.add("fuzz.pov", text);
    try {
        lumen::parser::parse_file(*file);
    } catch (const lumen::LumenError&) {
        return 0;  // the interpreter would stop at the same error
    } catch (const lumen::LumenError&) {
        return 0;
    }
#ifndef LUMEN_FUZZ_PARSER_ONLY
    if (parse_only()) return 0;
    try {
        lumen::interp::interpret_text(sources, "fuzz.pov", text, small_limits());
    } catch (const lumen::LumenError&) {
    } catch (const lumen::LumenError&) {
    }
#endif
    return 0;
}

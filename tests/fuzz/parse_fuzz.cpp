// libFuzzer target: the parser must turn any input into a syntax tree or a LumenError, and
// the interpreter and scene builders (with small limits, fuzz_input.hpp) into a scene or a
// LumenError; never crash, hang, leak or overflow the stack. Set LUMEN_FUZZ_PARSE_ONLY=1 to
// fuzz the parser alone (or build with -DLUMEN_FUZZ_PARSER_ONLY to link only the parser).
// Inputs it found are kept in tests/fuzz/regressions/, which the unit tests replay.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#ifndef LUMEN_FUZZ_PARSER_ONLY
#include "tests/fuzz/fuzz_input.hpp"
#endif
#include "base/diagnostics.hpp"
#include "parser/parser.hpp"

namespace {

#ifndef LUMEN_FUZZ_PARSER_ONLY
bool parse_only() {
    static const bool only = std::getenv("LUMEN_FUZZ_PARSE_ONLY") != nullptr;
    return only;
}
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    {
        lumen::SourceManager sources;
        const lumen::SourceFile* file = sources.add("fuzz.pov", text);
        try {
            lumen::parser::parse_file(*file);
        } catch (const lumen::LumenError& e) {
            lumen::format_diagnostic(e.diag);
            return 0;  // the interpreter would stop at the same error
        }
    }
#ifndef LUMEN_FUZZ_PARSER_ONLY
    if (!parse_only()) lumen::fuzz::evaluate("fuzz.pov", text);
#endif
    return 0;
}

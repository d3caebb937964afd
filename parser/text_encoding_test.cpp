// Files that are not SDL text: binary (an image #included by mistake) and UTF-16/32, refused
// with a located message before the grammar sees them; a UTF-8 byte order mark is fine.
#include "parser/text_encoding.hpp"

#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "parser/parser.hpp"

namespace lumen::parser {
namespace {

using namespace std::string_literals;

// The first line of the diagnostic parse_file gives for `text` ("" if it parses).
std::string problem(const std::string& text) {
    SourceFile f{"t.pov", text};
    try {
        parse_file(f);
    } catch (const LumenError& e) {
        return format_headline(e.diag);
    }
    return "";
}

TEST(TextEncoding, Utf16AndUtf32AreNamed) {
    const std::string le = "\xFF\xFE#\0v\0e\0r\0s\0i\0o\0n\0 \0" "3\0.\0" "7\0;\0"s;
    EXPECT_EQ(problem(le), "t.pov:1:1: error: 't.pov' is UTF-16 LE text: save it as UTF-8 (or ASCII) "
                           "to use it as a scene file");
    EXPECT_NE(problem(le.substr(2)).find("is UTF-16 LE text"), std::string::npos);  // no BOM
    std::string be;
    for (char c : std::string("sphere { 0, 1 }\n")) be += "\0"s + c;
    EXPECT_NE(problem(be).find("is UTF-16 BE text"), std::string::npos);
    EXPECT_NE(problem("\xFE\xFF" + be).find("is UTF-16 BE text"), std::string::npos);
    EXPECT_NE(problem("\xFF\xFE\0\0#\0\0\0"s).find("is UTF-32 LE text"), std::string::npos);
}

TEST(TextEncoding, BinaryFilesAreRefusedAtTheirFirstOddByte) {
    const std::string png = "\x89PNG\r\n\x1A\n\0\0\0\rIHDR\0\0\0\x02"s;
    EXPECT_EQ(problem(png), "t.pov:3:1: error: 't.pov' is a binary file (a PNG image), not SDL text "
                            "(byte 0x00 at offset 8)");
    EXPECT_NE(problem("#declare A = 1;\n\x01\x02\x03\x04\x05\x06\x07\x08\n").find("is a binary file"),
              std::string::npos);
    EXPECT_NE(problem("// text with a NUL \0 in a comment\n"s).find("is a binary file"), std::string::npos);
}

TEST(TextEncoding, TextIsAccepted) {
    EXPECT_EQ(problem("\xEF\xBB\xBFsphere { 0, 1 }\n"), "");       // UTF-8 byte order mark
    EXPECT_EQ(problem("// caf\xC3\xA9 \xE9t\xE9 (Latin-1)\r\nsphere { 0, 1 }\x1A"), "");
    EXPECT_EQ(problem("\tsphere {\f0, 1\v}\n"), "");
    // One stray control byte is left to the grammar, whose message escapes it.
    EXPECT_EQ(problem("sphere { 0, 1 }\n\x01\n"), "t.pov:2:1: error: unexpected a control character");
}

TEST(Printable, EscapesControlAndInvalidBytes) {
    EXPECT_EQ(printable("a\tb\nc\x1B[31m", false), "a\tb\\x0Ac\\x1B[31m");
    EXPECT_EQ(printable("a\nb", true), "a\nb");
    EXPECT_EQ(printable("caf\xC3\xA9 \xE9t\xE9", false), "caf\xC3\xA9 \\xE9t\\xE9");  // UTF-8 kept
    EXPECT_EQ(printable("\xC0\xAF \xED\xA0\x80 \xF4\x90\x80\x80 \xC2\x85", false),  // overlong,
              "\\xC0\\xAF \\xED\\xA0\\x80 \\xF4\\x90\\x80\\x80 \\xC2\\x85");   // surrogate, >U+10FFFF, C1
    EXPECT_EQ(display_width("caf\xC3\xA9"), 4u);
}

TEST(Printable, DiagnosticsNeverPrintRawBytes) {
    SourceFile f{"bin.pov", "\x89PNG\x01\x02 sphere\n"};
    Diagnostic d{Severity::Error, SourceLoc{&f, 1, 8, 7}, "unknown keyword '\x89PNG'", {}, {}};
    EXPECT_EQ(format_diagnostic(d),
              "bin.pov:1:8: error: unknown keyword '\\x89PNG'\n"
              "    \\x89PNG\\x01\\x02 sphere\n"
              "                    ^\n");
    SourceFile u{"u.pov", "caf\xC3\xA9 = 1\n"};  // the caret counts characters, not bytes
    EXPECT_EQ(format_diagnostic(Diagnostic{Severity::Error, SourceLoc{&u, 1, 7, 6}, "x", {}, {}}),
              "u.pov:1:7: error: x\n    caf\xC3\xA9 = 1\n         ^\n");
}

TEST(Printable, LongLinesAreCutAroundTheCaret) {
    SourceFile f{"long.pov", std::string(300, 'a') + "X" + std::string(300, 'b') + "\n"};
    const std::string out = format_diagnostic(Diagnostic{Severity::Error, SourceLoc{&f, 1, 301, 300}, "x", {}, {}});
    EXPECT_EQ(out, "long.pov:1:301: error: x\n    ..." + std::string(100, 'a') + "X" + std::string(199, 'b') +
                       "...\n       " + std::string(100, ' ') + "^\n");
}

}  // namespace
}  // namespace lumen::parser

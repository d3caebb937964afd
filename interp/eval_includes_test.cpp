// #include: search order, #local scoping per file, the include chain in diagnostics, limits.
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "interp/eval_test_support.hpp"

namespace lumen::interp::testing {
namespace {

namespace fs = std::filesystem;

class IncludeTest : public EvalTest {
protected:
    fs::path dir = fs::temp_directory_path() / ("lumen_inc_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir / "lib"); }
    void TearDown() override { fs::remove_all(dir); }
    void write(const std::string& rel, const std::string& text) { std::ofstream(dir / rel) << text; }
    // Runs `text` as if it were the file main.pov in the temporary folder.
    std::vector<Item> run_main_file(const std::string& text) { return run(text, (dir / "main.pov").string()); }
    std::string error_in_main(const std::string& text, Diagnostic* out = nullptr) {
        try {
            run_main_file(text);
        } catch (const LumenError& e) {
            if (out) *out = e.diag;
            return e.diag.message;
        }
        return "";
    }
};

TEST_F(IncludeTest, IncludedDeclaresAreVisibleAndLocalsAreNot) {
    write("defs.inc", "#declare Shared = 5;\n#local Private = 6;\n#declare Sum = Shared + Private;\n");
    run_main_file("#include \"defs.inc\"\n");
    EXPECT_DOUBLE_EQ(num_var("Shared"), 5);
    EXPECT_DOUBLE_EQ(num_var("Sum"), 11);
    EXPECT_DOUBLE_EQ(number("defined(Private)"), 0);
}

TEST_F(IncludeTest, IncludedItemsAreSplicedInPlace) {
    write("items.inc", "2, 3\n");
    auto items = run_main_file("1 #include \"items.inc\" 4\n");
    ASSERT_EQ(items.size(), 5u);
    EXPECT_DOUBLE_EQ(to_float(items[3].value), 3);
}

TEST_F(IncludeTest, LibraryPathsAreSearchedAfterTheSceneFolder) {
    write("lib/only_lib.inc", "#declare FromLib = 1;\n");
    write("both.inc", "#declare Which = \"scene\";\n");
    write("lib/both.inc", "#declare Which = \"lib\";\n");
    options.library_paths = {(dir / "lib").string()};
    options.default_include_path = false;
    run_main_file("#include \"only_lib.inc\"\n#include \"both.inc\"\n");
    EXPECT_DOUBLE_EQ(num_var("FromLib"), 1);
    EXPECT_EQ(str("Which"), "scene");
}

TEST_F(IncludeTest, SystemIncludeFolderIsUsedByDefault) {
    if (!fs::exists(fs::path(options.system_include_dir) / "math.inc")) GTEST_SKIP() << "POV-Ray includes not installed";
    EXPECT_DOUBLE_EQ(number("file_exists(\"math.inc\")"), 1);
    options.default_include_path = false;
    ev.reset();
    EXPECT_DOUBLE_EQ(number("file_exists(\"math.inc\")"), 0);
}

TEST_F(IncludeTest, IncExtensionIsOptional) {
    write("shapes_x.inc", "#declare Got = 1;\n");
    run_main_file("#include \"shapes_x\"\n");
    EXPECT_DOUBLE_EQ(num_var("Got"), 1);
}

TEST_F(IncludeTest, MissingIncludeIsAnErrorAtTheName) {
    Diagnostic d;
    EXPECT_EQ(error_in_main("\n#include \"nothere.inc\"\n", &d), "cannot find include file 'nothere.inc'");
    EXPECT_EQ(d.loc.line, 2u);
    EXPECT_EQ(d.loc.column, 10u);
}

TEST_F(IncludeTest, ErrorsInsideIncludesCarryTheChainInnermostFirst) {
    write("inner.inc", "#declare A = 1;\n#declare B = Oops;\n");
    write("outer.inc", "\n#include \"inner.inc\"\n");
    Diagnostic d;
    EXPECT_EQ(error_in_main("#include \"outer.inc\"\n", &d), "undeclared identifier 'Oops'");
    EXPECT_EQ(d.loc.line, 2u);
    EXPECT_NE(d.loc.file->name.find("inner.inc"), std::string::npos);
    ASSERT_EQ(d.include_chain.size(), 2u);
    EXPECT_NE(d.include_chain[0].file->name.find("outer.inc"), std::string::npos);
    EXPECT_EQ(d.include_chain[0].line, 2u);
    EXPECT_NE(d.include_chain[1].file->name.find("main.pov"), std::string::npos);
    EXPECT_EQ(d.include_chain[1].line, 1u);
}

TEST_F(IncludeTest, BinaryAndUtf16IncludesAreNamedWithTheChain) {
    using namespace std::string_literals;
    write("image.png", "\x89PNG\r\n\x1A\n\0\0\0\rIHDR"s);
    write("wide.inc", "\xFF\xFE#\0d\0"s);
    write("outer.inc", "#include \"image.png\"\n");
    Diagnostic d;
    EXPECT_EQ(error_in_main("#version 3.7;\n#include \"outer.inc\"\n", &d).rfind("'", 0), 0u);
    EXPECT_NE(d.message.find("is a binary file (a PNG image), not SDL text"), std::string::npos) << d.message;
    EXPECT_NE(d.loc.file->name.find("image.png"), std::string::npos);
    ASSERT_EQ(d.include_chain.size(), 2u);
    EXPECT_EQ(d.include_chain[0].line, 1u);
    EXPECT_NE(d.include_chain[1].file->name.find("main.pov"), std::string::npos);
    EXPECT_EQ(d.include_chain[1].line, 2u);
    const std::string shown = format_diagnostic(d);
    for (char c : shown) EXPECT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7F)) << shown;
    EXPECT_NE(error_in_main("#include \"wide.inc\"\n", &d).find("is UTF-16 LE text: save it as UTF-8"),
              std::string::npos);
    EXPECT_EQ(d.include_chain.size(), 1u);
}

TEST_F(IncludeTest, Utf8ByteOrderMarkIsAcceptedInIncludes) {
    // POV-Ray 3.7 accepts it only in the scene file ("Illegal character ... ef" in an include).
    write("bom.inc", "\xEF\xBB\xBF#declare FromBom = 3;\n");
    run_main_file("\xEF\xBB\xBF#include \"bom.inc\"\n");
    EXPECT_DOUBLE_EQ(num_var("FromBom"), 3);
}

TEST_F(IncludeTest, RecursiveIncludeHitsTheDepthLimit) {
    write("self.inc", "#include \"self.inc\"\n");
    options.max_include_depth = 10;
    Diagnostic d;
    EXPECT_EQ(error_in_main("#include \"self.inc\"\n", &d), "include files nested more than 10 deep");
    EXPECT_EQ(d.include_chain.size(), 10u);
}

TEST_F(IncludeTest, RepeatedIncludesRunEachTime) {
    write("count.inc", "#declare N = N + 1;\n");
    run_main_file("#declare N = 0;\n#include \"count.inc\"\n#include \"count.inc\"\n#include \"count.inc\"\n");
    EXPECT_DOUBLE_EQ(num_var("N"), 3);
}

TEST_F(IncludeTest, MacrosFromIncludesWork) {
    write("m.inc", "#macro Twice(A) 2 * A #end\n");
    run_main_file("#include \"m.inc\"\n#declare R = Twice(21);\n");
    EXPECT_DOUBLE_EQ(num_var("R"), 42);
}

TEST_F(IncludeTest, SyntaxErrorsInIncludesAreReportedInThatFile) {
    write("bad.inc", "#declare = 3;\n");
    Diagnostic d;
    EXPECT_NE(error_in_main("#include \"bad.inc\"\n", &d), "");
    ASSERT_NE(d.loc.file, nullptr);
    EXPECT_NE(d.loc.file->name.find("bad.inc"), std::string::npos);
    EXPECT_EQ(d.include_chain.size(), 1u);
}

}  // namespace
}  // namespace lumen::interp::testing

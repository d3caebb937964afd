// INI files: sections, comments, switch lines, nesting (POV-Ray 3.7's rules).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/command_line.hpp"
#include "cli/ini_file.hpp"
#include "base/diagnostics.hpp"

namespace lumen::cli {
namespace {

namespace fs = std::filesystem;

// A scratch folder with INI files, removed at the end of each test.
class IniFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("lumen_ini_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    Options parse(std::vector<std::string> args) { return parse_command_line(args, sources_); }

    fs::path dir_;
    SourceManager sources_;
};

const char* kSectioned =
    "; POV-Ray style INI\n"
    "Width=40   ; trailing comment\n"
    "Height=30\n"
    "\n"
    "[big]\n"
    "Width=100\n"
    "Height=75\n"
    "[Other]\n"
    "Width=7\n";

TEST_F(IniFiles, LinesBeforeTheFirstSectionAlwaysApply) {
    const std::string ini = write("t.ini", kSectioned);
    const Options o = parse({"s.pov", ini});
    EXPECT_EQ(o.render.width, 40);  // VERIFIED in POV: t.ini gives 40x30
    EXPECT_EQ(o.render.height, 30);
}

TEST_F(IniFiles, NamedSectionApplies) {
    const std::string ini = write("t.ini", kSectioned);
    Options o = parse({"s.pov", ini + "[big]"});
    EXPECT_EQ(o.render.width, 100);  // VERIFIED in POV: "t.ini[big]" gives 100x75
    EXPECT_EQ(o.render.height, 75);
    o = parse({"s.pov", ini + "[other]"});  // section names are case-insensitive
    EXPECT_EQ(o.render.width, 7);
    EXPECT_EQ(o.render.height, 30);
}

TEST_F(IniFiles, SwitchLinesDeclaresAndLaterSettingsWin) {
    const std::string ini = write("s.ini",
                                  "+W64 +H48 +A0.1   # switches on one line\n"
                                  "declare=Size=2.5\n"
                                  "Declare=Title=\"a; b\"\n"
                                  "Input_File_Name=from_ini.pov\n");
    const Options o = parse({ini, "+W32"});
    EXPECT_EQ(o.render.width, 32);  // the command line after the INI file wins
    EXPECT_EQ(o.render.height, 48);
    EXPECT_TRUE(o.render.antialias);
    EXPECT_DOUBLE_EQ(o.render.aa_threshold, 0.1);
    EXPECT_EQ(o.input, "from_ini.pov");
    ASSERT_EQ(o.scene.declares.size(), 2u);
    EXPECT_DOUBLE_EQ(*o.scene.declares[0].number, 2.5);
    EXPECT_EQ(o.scene.declares[1].text, "a; b");  // ';' inside quotes is not a comment
}

TEST_F(IniFiles, IncludeIniNests) {
    write("inner.ini", "Height=12\n");
    const std::string outer = write("outer.ini", "Include_Ini=" + (dir_ / "inner.ini").string() +
                                                     "\nWidth=11\n");
    const Options o = parse({"s.pov", outer});
    EXPECT_EQ(o.render.width, 11);
    EXPECT_EQ(o.render.height, 12);
}

TEST_F(IniFiles, IncludeLoopIsAnError) {
    const std::string loop = (dir_ / "loop.ini").string();
    write("loop.ini", "Include_Ini=" + loop + "\n");
    try {
        parse({"s.pov", loop});
        FAIL() << "expected an error";
    } catch (const LumenError& e) {
        EXPECT_NE(e.diag.message.find("nested more than"), std::string::npos);
    }
}

TEST_F(IniFiles, ErrorsPointIntoTheFile) {
    const std::string ini = write("bad.ini", "Width=10\n  Heigth=5\n");
    try {
        parse({"s.pov", ini});
        FAIL() << "expected an error";
    } catch (const LumenError& e) {
        EXPECT_EQ(e.diag.message, "unknown option 'Heigth'");
        EXPECT_EQ(e.diag.hint, "did you mean 'Height'?");
        EXPECT_EQ(e.diag.loc.line, 2u);
        EXPECT_EQ(e.diag.loc.column, 3u);
        ASSERT_NE(e.diag.loc.file, nullptr);
        EXPECT_EQ(e.diag.loc.file->name, ini);
    }
}

TEST_F(IniFiles, MissingFileIsAnError) {
    try {
        parse({"s.pov", (dir_ / "nope.ini").string()});
        FAIL() << "expected an error";
    } catch (const LumenError& e) {
        EXPECT_NE(e.diag.message.find("cannot read INI file"), std::string::npos);
    }
}

TEST(IniSpec, SplitsSection) {
    EXPECT_EQ(split_ini_spec("file.ini[Big]"), std::make_pair(std::string("file.ini"), std::string("Big")));
    EXPECT_EQ(split_ini_spec("\"my file.ini[x y]\""),
              std::make_pair(std::string("my file.ini"), std::string("x y")));
    EXPECT_EQ(split_ini_spec("plain.ini"), std::make_pair(std::string("plain.ini"), std::string()));
}

TEST(IniText, LibraryFolderArgument) {
    SourceManager sources;
    const Options o = parse_command_line({"s.pov", "/some/include/"}, sources);
    ASSERT_EQ(o.scene.library_paths.size(), 1u);
    EXPECT_EQ(o.scene.library_paths[0], "/some/include/");
}

}  // namespace
}  // namespace lumen::cli

// The whole program on small scenes: exit statuses, output files, frames, --check, errors.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/run.hpp"

namespace lumen::cli {
namespace {

namespace fs = std::filesystem;

const char* kScene =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 }\n"
    "camera { location <0, 0, -4> look_at 0 }\n"
    "light_source { <3, 5, -4> rgb 1 }\n"
    "sphere { <clock, 0, 0>, 1 pigment { rgb <1, 0.4, 0.2> } }\n";

// Runs lumen in a scratch folder (the default output goes to the current folder).
class RunTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("lumen_run_test_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
        old_ = fs::current_path();
        fs::current_path(dir_);
    }
    void TearDown() override {
        fs::current_path(old_);
        fs::remove_all(dir_);
    }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
    // Runs with stdout captured into `out`.
    int run(std::vector<std::string> args, std::string* out = nullptr) {
        std::fflush(stdout);
        const int saved = dup(fileno(stdout));
        const fs::path capture = dir_ / "stdout.txt";
        std::FILE* f = std::fopen(capture.c_str(), "w");
        dup2(fileno(f), fileno(stdout));
        const int status = run_command_line(args);
        std::fflush(stdout);
        dup2(saved, fileno(stdout));
        close(saved);
        std::fclose(f);
        if (out) {
            std::ifstream in(capture);
            out->assign(std::istreambuf_iterator<char>(in), {});
        }
        return status;
    }

    fs::path dir_, old_;
};

TEST_F(RunTest, RendersToTheDefaultName) {
    write("ball.pov", kScene);
    EXPECT_EQ(run({"ball.pov", "+W16", "+H12"}), 0);
    EXPECT_TRUE(fs::exists(dir_ / "ball.png"));
    EXPECT_EQ(run({"ball.pov", "+W16", "+H12", "+FP", "+Oother"}), 0);
    EXPECT_TRUE(fs::exists(dir_ / "other.ppm"));
}

TEST_F(RunTest, AnimationWritesNumberedFrames) {
    write("anim.pov", kScene);
    EXPECT_EQ(run({"anim.pov", "+W8", "+H6", "+KFI1", "+KFF10", "+SF9"}), 0);
    EXPECT_FALSE(fs::exists(dir_ / "anim08.png"));  // before the subset
    EXPECT_TRUE(fs::exists(dir_ / "anim09.png"));
    EXPECT_TRUE(fs::exists(dir_ / "anim10.png"));
}

TEST_F(RunTest, ErrorsExitWithOneAndWriteNoImage) {
    write("bad.pov", "#version 3.7;\nsphere { 0, 1 pigment { colour Nope } }\n");
    EXPECT_EQ(run({"bad.pov", "+W8", "+H6"}), 1);
    EXPECT_FALSE(fs::exists(dir_ / "bad.png"));
    EXPECT_EQ(run({"missing.pov"}), 1);
    EXPECT_EQ(run({"bad.pov", "+Zz"}), 1);
}

TEST_F(RunTest, DeepLegalRecursionDoesNotOverflow) {
    // 150 nested macro calls (under the interpreter's limit of 200) need a deep stack.
    write("deep.pov",
          "#version 3.7;\n#macro Down(n) #if (n > 0) Down(n - 1) #end #end\nDown(150)\n"
          "camera { location -4 look_at 0 }\n");
    EXPECT_EQ(run({"deep.pov", "--check"}), 0);
}

TEST_F(RunTest, CheckListsNothingForACoreScene) {
    write("ball.pov", kScene);
    std::string out;
    EXPECT_EQ(run({"ball.pov", "--check"}, &out), 0);
    EXPECT_EQ(out, "no unsupported features\n");
    EXPECT_FALSE(fs::exists(dir_ / "ball.png"));
}

TEST_F(RunTest, DumpScenePrintsJson) {
    write("ball.pov", kScene);
    std::string out;
    EXPECT_EQ(run({"ball.pov", "--dump-scene", "+K0.5"}, &out), 0);
    ASSERT_FALSE(out.empty());
    EXPECT_EQ(out.front(), '{');
    EXPECT_NE(out.find("\"objects\""), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "ball.png"));
}

TEST_F(RunTest, HelpAndVersion) {
    std::string out;
    EXPECT_EQ(run({"--help"}, &out), 0);
    EXPECT_NE(out.find("usage: lumen scene.pov"), std::string::npos);
    EXPECT_NE(out.find("+KFI"), std::string::npos);
    EXPECT_EQ(run({"--version"}, &out), 0);
    EXPECT_EQ(out.rfind("lumen ", 0), 0u);
}

// #fopen may write beside the scene file and beside the output image, and nowhere else
// outside the working folder: here the scene, the image and the working folder are apart.
TEST_F(RunTest, UserFilesGoToTheScenesOrTheOutputFolder) {
    for (const char* d : {"work", "scene", "out", "elsewhere"}) fs::create_directories(dir_ / d);
    fs::current_path(dir_ / "work");
    std::string scene = kScene;
    for (const char* d : {"scene", "out"})
        scene += "#fopen F \"" + (dir_ / d / "w.txt").string() + "\" write #fclose F\n";
    write("scene/s.pov", scene);
    EXPECT_EQ(run({"../scene/s.pov", "+W8", "+H8", "+O../out/img.png"}), 0);
    EXPECT_TRUE(fs::exists(dir_ / "scene" / "w.txt"));
    EXPECT_TRUE(fs::exists(dir_ / "out" / "w.txt"));
    write("scene/e.pov", std::string(kScene) + "#fopen F \"" +
                             (dir_ / "elsewhere" / "w.txt").string() + "\" write\n");
    EXPECT_NE(run({"../scene/e.pov", "+W8", "+H8", "+O../out/img.png"}), 0);
    EXPECT_FALSE(fs::exists(dir_ / "elsewhere" / "w.txt"));
    EXPECT_EQ(run({"../scene/e.pov", "+W8", "+H8", "-F", "Permitted_Path=../elsewhere"}), 0);
    EXPECT_TRUE(fs::exists(dir_ / "elsewhere" / "w.txt"));
}

std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Tiles on the block grid (+BS8) rendered as separate runs (adaptive AA, an area light, one-
// and two-thread runs) and merged give the file one run writes, byte for byte, overlapping
// parts included; parts of different renders are refused.
TEST_F(RunTest, MergedTilesAreTheWholeRenderByteForByte) {
    write("tiles.pov", std::string(kScene) +
                           "light_source { <-3, 4, -2> rgb 0.5 area_light x, y, 3, 3 jitter }\n"
                           "plane { y, -1 pigment { checker rgb 1 rgb 0.2 } }\n");
    const std::vector<std::string> common = {"tiles.pov", "+W40", "+H30", "+A0.1", "+AM2", "+R2", "+BS8"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> a = common;
        a.insert(a.end(), extra.begin(), extra.end());
        return a;
    };
    ASSERT_EQ(run(with({"+Owhole.png", "+WT2"})), 0);
    ASSERT_EQ(run(with({"+Oa.png", "+WT1", "+SR1", "+ER16", "+SC1", "+EC40"})), 0);
    ASSERT_EQ(run(with({"+Ob.png", "+WT2", "+SR17", "+ER30", "+SC1", "+EC24"})), 0);
    ASSERT_EQ(run(with({"+Oc.png", "+WT1", "+SR9", "+ER30", "+SC17", "+EC40"})), 0);  // overlaps a and b
    EXPECT_NE(bytes_of(dir_ / "a.png"), bytes_of(dir_ / "whole.png"));
    ASSERT_EQ(run({"merge", "merged.png", "a.png", "b.png", "c.png"}), 0);
    EXPECT_EQ(bytes_of(dir_ / "merged.png"), bytes_of(dir_ / "whole.png"));
    // Cropped parts (Output_Crop), placed by position.
    ASSERT_EQ(run(with({"+Oe.png", "+SR1", "+ER8", "+SC1", "+EC40", "Output_Crop=on"})), 0);
    ASSERT_EQ(run(with({"+Of.png", "+SR9", "+ER30", "+SC1", "+EC40", "Output_Crop=on"})), 0);
    EXPECT_LT(bytes_of(dir_ / "e.png").size(), bytes_of(dir_ / "a.png").size());
    ASSERT_EQ(run({"merge", "cropped.png", "--size=40,30", "e.png", "--at=0,8", "f.png"}), 0);
    EXPECT_EQ(bytes_of(dir_ / "cropped.png"), bytes_of(dir_ / "whole.png"));
    EXPECT_EQ(run({"merge", "bad.png", "--size=40,30", "--at=0,9", "f.png"}), 1);  // off the edge

    std::string other = bytes_of(dir_ / "tiles.pov");
    other.replace(other.find("0.4, 0.2"), 8, "0.2, 0.4");
    write("other.pov", other);
    ASSERT_EQ(run({"other.pov", "+W40", "+H30", "+Od.png"}), 0);
    EXPECT_EQ(run({"merge", "bad.png", "a.png", "d.png"}), 1);  // another scene
    EXPECT_FALSE(fs::exists(dir_ / "bad.png"));
    EXPECT_EQ(run({"merge", "bad.png"}), 1);
    EXPECT_EQ(run({"merge", "bad.ppm", "a.png"}), 1);
}

}  // namespace
}  // namespace lumen::cli

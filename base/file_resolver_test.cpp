#include "base/file_resolver.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace lumen {
namespace {

namespace fs = std::filesystem;

class FileResolverTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("lumen-resolver-" + std::to_string(::getpid()));
        for (const char* d : {"scene", "lib1", "lib2", "system"}) fs::create_directories(root_ / d);
    }
    void TearDown() override { fs::remove_all(root_); }
    std::string touch(const std::string& rel) {
        std::ofstream(root_ / rel) << "x";
        return (root_ / rel).lexically_normal().string();
    }
    FileResolver resolver() const {
        return FileResolver(SearchPath{(root_ / "scene").string(),
                                       {(root_ / "lib1").string(), (root_ / "lib2").string()},
                                       (root_ / "system").string()});
    }
    fs::path root_;
};

TEST_F(FileResolverTest, SceneFolderThenLibraryPathsInOrderThenTheInstalledFolder) {
    const std::string sys = touch("system/a.inc");
    EXPECT_EQ(resolver().find("a.inc", FileResolver::Kind::Include), sys);
    const std::string lib2 = touch("lib2/a.inc");
    EXPECT_EQ(resolver().find("a.inc", FileResolver::Kind::Include), lib2);
    const std::string lib1 = touch("lib1/a.inc");
    EXPECT_EQ(resolver().find("a.inc", FileResolver::Kind::Include), lib1);
    const std::string scene = touch("scene/a.inc");
    EXPECT_EQ(resolver().find("a.inc", FileResolver::Kind::Include), scene);
}

TEST_F(FileResolverTest, AddsTheKindsExtensionsToANameWithoutOne) {
    const std::string inc = touch("lib1/colors.inc");
    EXPECT_EQ(resolver().find("colors", FileResolver::Kind::Include), inc);
    const std::string png = touch("lib2/wall.png");
    EXPECT_EQ(resolver().find("wall", FileResolver::Kind::Image), png);
    EXPECT_EQ(resolver().find("wall", FileResolver::Kind::Include), "");
    const std::string ttf = touch("system/timrom.ttf");
    EXPECT_EQ(resolver().find("timrom", FileResolver::Kind::Font), ttf);
    // The name as written comes first in each folder.
    const std::string bare = touch("lib1/colors");
    EXPECT_EQ(resolver().find("colors", FileResolver::Kind::Include), bare);
}

TEST_F(FileResolverTest, AbsoluteNamesAreTakenAsTheyAreAndFoldersAreNotFiles) {
    const std::string abs = touch("lib2/b.df3");
    EXPECT_EQ(resolver().find(abs, FileResolver::Kind::DensityFile), abs);
    EXPECT_EQ(resolver().find((root_ / "lib2/missing.df3").string(), FileResolver::Kind::DensityFile), "");
    EXPECT_EQ(resolver().find("lib1", FileResolver::Kind::DataFile), "");  // only folders there
    EXPECT_EQ(resolver().find("", FileResolver::Kind::DataFile), "");
}

}  // namespace
}  // namespace lumen

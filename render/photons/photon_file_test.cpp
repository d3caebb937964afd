// Photon map files: what is saved loads back, and a damaged or foreign file is refused with the
// location of the keyword that named it.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "render/photons/photon_file.hpp"

namespace lumen::render {
namespace {

namespace fs = std::filesystem;

class PhotonFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("lumen_photon_file_" + std::to_string(std::random_device{}()));
        fs::create_directories(dir);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int i = 0; i < 500; ++i)
            pass.surface.add(make_photon({u(rng), u(rng), u(rng)}, {0.5 + u(rng) / 4, 0.3, 0.1},
                                         {u(rng), 1, u(rng)}));
        pass.surface.build();
        pass.shot = 1234;
        pass.spacing = 0.015;
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string error_loading(const std::string& path) {
        PhotonPass loaded;
        try {
            load_photons(loaded, path, loc);
        } catch (const LumenError& e) {
            EXPECT_EQ(e.diag.loc.file, &file);
            EXPECT_EQ(e.diag.loc.line, 3u);
            return e.what();
        }
        return "";
    }
    fs::path dir;
    PhotonPass pass;
    SourceFile file{"scene.pov", ""};
    SourceLoc loc{&file, 3, 14, 0};
};

bool same_photon(const Photon& a, const Photon& b) {
    return std::memcmp(a.position, b.position, sizeof a.position) == 0 &&
           std::memcmp(a.rgbe, b.rgbe, sizeof a.rgbe) == 0 && a.theta == b.theta && a.phi == b.phi;
}

TEST_F(PhotonFile, SavedMapLoadsBack) {
    const std::string path = (dir / "map.ph").string();
    save_photons(pass, path, loc);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
    PhotonPass loaded;
    load_photons(loaded, path, loc);
    EXPECT_EQ(loaded.shot, 1234u);
    EXPECT_EQ(loaded.spacing, 0.015);
    ASSERT_EQ(loaded.surface.size(), pass.surface.size());
    for (size_t i = 0; i < pass.surface.size(); ++i) {  // in the saved tree's order
        EXPECT_TRUE(same_photon(pass.surface.photons()[i], loaded.surface.photons()[i]));
        EXPECT_EQ(pass.surface.photons()[i].axis, loaded.surface.photons()[i].axis);
    }
    // The tree is usable: the same photons are gathered from both maps.
    GatheredPhotons a, b;
    pass.surface.gather({0.1, 0.2, 0.3}, {0, 1, 0}, 0.5, 30, a);
    loaded.surface.gather({0.1, 0.2, 0.3}, {0, 1, 0}, 0.5, 30, b);
    ASSERT_EQ(a.count(), b.count());
    EXPECT_EQ(a.radius_sq, b.radius_sq);
}

TEST_F(PhotonFile, DamagedFilesAreRefusedAtTheKeyword) {
    const std::string path = (dir / "map.ph").string();
    EXPECT_EQ(error_loading(path), "photon map file '" + path + "': cannot be read");
    { std::ofstream(path) << "P6\n1 1\n255\nabc"; }
    EXPECT_NE(error_loading(path).find("not a lumen photon map"), std::string::npos);
    save_photons(pass, path, loc);
    fs::resize_file(path, fs::file_size(path) - 5);
    EXPECT_NE(error_loading(path).find("truncated or damaged (500 photons announced)"),
              std::string::npos);
    { std::ofstream(path) << "lumen-photons 1\n4000000000000 10 0.1\n"; }
    EXPECT_NE(error_loading(path).find("truncated or damaged"), std::string::npos);
    { std::ofstream(path) << "lumen-photons 2\n0 0 0.1\n"; }
    EXPECT_NE(error_loading(path).find("version 2"), std::string::npos);
}

TEST_F(PhotonFile, UnwritablePathIsAnError) {
    const std::string path = (dir / "no" / "such" / "dir" / "map.ph").string();
    try {
        save_photons(pass, path, loc);
        FAIL() << "saved into a missing directory";
    } catch (const LumenError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot be written"), std::string::npos);
    }
}

}  // namespace
}  // namespace lumen::render

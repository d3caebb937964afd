#include "render/photons/photon_file.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "base/whole_file.hpp"

namespace lumen::render {

namespace {

constexpr const char* kMagic = "lumen-photons";
constexpr int kVersion = 1;

[[noreturn]] void bad_file(const SourceLoc& loc, const std::string& path, const std::string& why) {
    throw LumenError(loc, "photon map file '" + path + "': " + why);
}

}  // namespace

void save_photons(const PhotonPass& pass, const std::string& path, const SourceLoc& loc) {
    const std::string why = write_whole_file(path, [&](std::ostream& out) {
        const std::vector<Photon>& photons = pass.surface.photons();
        out << kMagic << ' ' << kVersion << '\n'
            << photons.size() << ' ' << pass.shot << ' ';
        char spacing[32];
        std::snprintf(spacing, sizeof spacing, "%.17g", pass.spacing);
        out << spacing << '\n';
        out.write(reinterpret_cast<const char*>(photons.data()),
                  std::streamsize(photons.size() * sizeof(Photon)));
    });
    if (!why.empty()) bad_file(loc, path, why);
}

void load_photons(PhotonPass& pass, const std::string& path, const SourceLoc& loc) {
    std::ifstream in(path, std::ios::binary);
    if (!in) bad_file(loc, path, "cannot be read");
    std::string magic;
    int version = 0;
    size_t count = 0;
    if (!(in >> magic >> version) || magic != kMagic) bad_file(loc, path, "not a lumen photon map");
    if (version != kVersion)
        bad_file(loc, path, "version " + std::to_string(version) + " (lumen reads 1)");
    if (!(in >> count >> pass.shot >> pass.spacing) || in.get() != '\n')
        bad_file(loc, path, "malformed header");
    // The count must match what the file holds before anything is allocated for it.
    const std::streamoff start = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg() - start;
    if (size < 0 || uint64_t(size) != uint64_t(count) * sizeof(Photon))
        bad_file(loc, path, "truncated or damaged (" + std::to_string(count) + " photons announced)");
    in.seekg(start);
    std::vector<Photon> photons(count);
    in.read(reinterpret_cast<char*>(photons.data()), std::streamsize(count * sizeof(Photon)));
    if (!in) bad_file(loc, path, "truncated");
    for (const Photon& p : photons)
        if (!std::isfinite(p.position[0] + p.position[1] + p.position[2]) || p.axis > 2)
            bad_file(loc, path, "damaged photon record");
    if (!std::isfinite(pass.spacing)) bad_file(loc, path, "non-finite spacing");
    pass.surface.assign_built(std::move(photons));
}

}  // namespace lumen::render

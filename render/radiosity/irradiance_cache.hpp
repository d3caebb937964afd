// A Ward-style irradiance cache, used by several threads at once (Ward 1988; with Ward and
// Heckbert's gradients where the gather gives them, which POV-Ray does not use): a point reuses the records whose error e = |d|/R + sqrt(1 − n·n') is below the
// cache error a; its value is the average of every record with e < 3a weighted (1 − e/3a)²,
// so weights fade to 0 at the edge of a record's reach: no seams where the set of records
// changes, and each value averages several records' ray noise. (Plain Ward weights 1/e over
// e < a gave blotches and per-record noise: cornell MAE 0.0033 at a = 0.05, now 0.0025.)
#pragma once
#include <array>
#include <cstdint>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "render/radiosity/irradiance_gradients.hpp"

namespace lumen::render::radiosity {

struct CacheSettings {
    double error = 0.3;                         // Ward's a
    double min_reuse = 0.015, max_reuse = 0.2;  // a record's radius × distance to the camera
    glm::dvec3 camera{0};
};

class IrradianceCache {
public:
    // `extent`: a far corner of the scene, which sizes the lookup grid.
    IrradianceCache(const CacheSettings& settings, const glm::dvec3& extent);

    // The faded average of the records within 3a of p (normal n); false when none is within a.
    bool lookup(const glm::dvec3& p, const glm::dvec3& n, glm::dvec3& out) const;
    // A new record at p with incident light G, its radius the gather's harmonic mean distance
    // clamped by the reuse limits.
    // `gradients` (irradiance_gradients.hpp) extrapolate the record to nearby points.
    void insert(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& G,
                double harmonic_distance, const IrradianceGradients& gradients = {});
    size_t size() const;
    const CacheSettings& settings() const { return s_; }

private:
    struct Record {
        glm::dvec3 position, normal, G;
        double radius;
        IrradianceGradients gradients;
    };
    // Records live in a grid per level, level k's cells 2^k base cells wide; a record goes to
    // the first level whose cells are as wide as its reach (so at most 2 cells per axis: far
    // records with huge radii stay cheap), and a lookup visits one cell per level in use.
    using Cell = std::array<long long, 4>;  // x, y, z, level
    struct CellHash {
        size_t operator()(const Cell& c) const {
            return size_t(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL ^
                          c[3] * 2654435761LL);
        }
    };
    Cell cell_of(const glm::dvec3& p, int level) const;

    CacheSettings s_;
    double cell_ = 1;
    mutable std::shared_mutex mutex_;
    std::vector<Record> records_;
    // What a lookup reads of each record in a cell before it needs the record: most records
    // of a cell lie beyond their reach (3a R) from the point.
    struct Entry {
        glm::dvec3 position;
        double reach2;  // (3 a R)^2
        uint32_t index;
    };
    std::unordered_map<Cell, std::vector<Entry>, CellHash> grid_;
    uint64_t levels_ = 0;  // bit k: level k holds records
};

}  // namespace lumen::render::radiosity

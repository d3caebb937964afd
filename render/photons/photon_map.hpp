// A photon map as POV-Ray 3.7 keeps one: photons stored compactly (single-precision position,
// RGBE colour, the direction they came from in two bytes), a kd-tree implicit in the array,
// and the nearest-photon gather with POV's flattened distance and its adaptive radius.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace lumen::render {

struct Photon {
    float position[3];
    uint8_t rgbe[4];     // colour: three mantissas and a shared exponent (POV's packing)
    int8_t theta, phi;   // direction towards where the photon came from
    uint8_t axis;        // the kd-tree's split axis at this photon

    glm::dvec3 colour() const;
    glm::dvec3 direction() const;  // unit
};

// Packs a colour and a direction as POV-Ray does (values of 32 and more overflow, as there).
Photon make_photon(const glm::dvec3& position, const glm::dvec3& colour,
                   const glm::dvec3& towards_origin);

// One gather's result: the photons kept and the radius² they cover.
struct GatheredPhotons {
    std::vector<const Photon*> photons;
    std::vector<double> distances;  // heap keys, parallel to `photons`
    double radius_sq = 0;
    int count() const { return int(photons.size()); }
};

struct GatherSettings {
    int min = 20, max = 100;          // gather Min, Max
    double expand_percent = 0.2;      // expand_thresholds
    int expand_min = 35;
    double radius = 0;                // the start radius (set by PhotonMap::choose_radius)
};

class PhotonMap {
public:
    void add(const Photon& p) { photons_.push_back(p); }
    void append(const std::vector<Photon>& more) {
        photons_.insert(photons_.end(), more.begin(), more.end());
    }
    size_t size() const { return photons_.size(); }
    bool empty() const { return photons_.empty(); }
    const std::vector<Photon>& photons() const { return photons_; }

    // Sorts the array into the kd-tree (each range split at its median on its widest axis).
    void build();
    // Takes an array build() left (a saved map) as the tree it is: building it again could
    // order ties otherwise, and the loaded map would gather differently from the saved one.
    // A damaged order gathers wrongly but safely (the tree is implicit in the index ranges).
    void assign_built(std::vector<Photon> photons) {
        photons_ = std::move(photons);
        bound_ranges();
    }
    // POV's automatic start radius from the photon density around sample photons (`radius`
    // not given), times `multiplier`; deterministic. `volume`: a media map, whose density is
    // per volume (n over 4/3 πr³) and whose radius POV-Ray doubles.
    double choose_radius(int gather_max, double multiplier, bool volume = false) const;

    // The up to `max` nearest photons within `radius` of p. With a normal (non-zero), distances
    // are flattened towards the surface: |v|²(1 + 16|n·v|), POV's ellipsoid.
    void gather(const glm::dvec3& p, const glm::dvec3& normal, double radius, int max,
                GatheredPhotons& out) const;
    // The adaptive gather: once at the start radius, and once more at three times it when
    // fewer than `min` were found, kept where POV's expand thresholds accept it.
    void gather_adaptive(const glm::dvec3& p, const glm::dvec3& normal, const GatherSettings& s,
                         GatheredPhotons& out) const;

    // A box around the photons of each range of the tree of at least kBoundedRange photons,
    // by the range's number in heap order (the whole map 1, range k's halves 2k and 2k + 1).
    struct Bounds {
        float lo[3], hi[3];
    };
    static constexpr int kBoundedRange = 64;

private:
    void subdivide(int start, int end);
    void bound_ranges();
    Bounds bound_range(int start, int end, size_t node);
    std::vector<Photon> photons_;
    std::vector<Bounds> bounds_;
};

}  // namespace lumen::render

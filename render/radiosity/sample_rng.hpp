// The random numbers of radiosity's ray sampling: SplitMix64 (Steele, Lea and Flood 2014).
// A gather seeds one generator per vertex side or cache point, thousands of times per frame:
// std::mt19937_64 spent more time filling its 312-word state than the rays took to aim.
#pragma once
#include <cstdint>

namespace lumen::render::radiosity {

class SampleRng {
public:
    explicit SampleRng(uint64_t seed) : state_(seed) {}

    uint64_t next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1), 53 bits.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }

private:
    uint64_t state_;
};

}  // namespace lumen::render::radiosity

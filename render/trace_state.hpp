// Per-thread mutable state of the tracer: counters, the random source for area-light jitter
// and crand, and scratch space reused across rays (so tracing never allocates per ray).
#pragma once
#include <bit>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "render/intersector.hpp"

namespace lumen::render {

struct TraceCounters {
    uint64_t rays = 0, shadow_rays = 0;
};

// std::minstd_rand read through std::uniform_real_distribution<double>(0, 1), number for
// number (libstdc++ makes each double of two draws, low then high), with the two draws made
// from the one state (a^2 x mod m for the second) so that neither waits on the other: a
// jittered area light draws two numbers for each of its shadow rays.
class UniformSource {
public:
    explicit UniformSource(uint32_t seed) { this->seed(seed); }
    void seed(uint32_t s) {
        x_ = s % kM;
        if (x_ == 0) x_ = 1;  // as minstd_rand seeds
    }
    double operator()() {
        constexpr double r = double(kM - 1);  // the values a draw takes: 1 .. m - 1
        const uint64_t low = kA * x_ % kM, high = kA2 * x_ % kM;
        x_ = high;
        const double u = (double(low - 1) + double(high - 1) * r) / (r * r);
        return u < 1 ? u : 0x1.fffffffffffffp-1;  // the largest double below 1
    }

private:
    static constexpr uint64_t kM = 2147483647, kA = 48271, kA2 = kA * kA % kM;
    uint64_t x_;
};

struct ThreadState {
    TraceCounters counters;
    UniformSource rng{12345};
    // Area-light grid cache (one slot per sample; `valid` marks filled slots).
    std::vector<glm::dvec3> area_filter;
    std::vector<unsigned char> area_valid;
    // Per light, by its place in the render's list: the object that last blocked its shadow
    // rays on this thread, tested first by the next one.
    std::vector<Occluder> occluders;
    Occluder* occluder(size_t light) {
        if (light >= occluders.size()) occluders.resize(light + 1);
        return &occluders[light];
    }

    // The render block this thread is on (BlockRenderer counts them). Scratch that an
    // IndirectLight keeps per block (radiosity's point-gather caches) is tagged with it, so a
    // new block starts afresh: a pixel's value then depends on its block alone, not on which
    // thread rendered which blocks before it, nor on the blocks a partial render leaves out.
    uint64_t block = 0;
    std::shared_ptr<void> block_scratch;
    const void* block_scratch_owner = nullptr;
    uint64_t block_scratch_block = 0;

    double uniform() { return rng(); }

    // Restarts the random source from a camera sample's position, so that what a sample draws
    // does not depend on which thread renders it, or on which pixels came before it (a partial
    // render's pixels are the whole render's: lumen farm).
    void reseed(double x, double y) {
        uint64_t h = std::bit_cast<uint64_t>(x) * 0x9e3779b97f4a7c15ULL ^ std::bit_cast<uint64_t>(y);
        h ^= h >> 31;  // splitmix64's finaliser
        h *= 0xbf58476d1ce4e5b9ULL;
        h ^= h >> 27;
        h *= 0x94d049bb133111ebULL;
        h ^= h >> 31;
        rng.seed(uint32_t(1 + h % 2147483646u));  // seeds 1 .. 2^31 - 2
    }
};

}  // namespace lumen::render

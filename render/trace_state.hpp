// Per-thread mutable state of the tracer: counters, the random source for area-light jitter
// and crand, and scratch space reused across rays (so tracing never allocates per ray).
#pragma once
#include <bit>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include <glm/vec3.hpp>

namespace lumen::render {

struct TraceCounters {
    uint64_t rays = 0, shadow_rays = 0;
};

struct ThreadState {
    TraceCounters counters;
    std::minstd_rand rng{12345};
    // Area-light grid cache (one slot per sample; `valid` marks filled slots).
    std::vector<glm::dvec3> area_filter;
    std::vector<unsigned char> area_valid;

    // The render block this thread is on (BlockRenderer counts them). Scratch that an
    // IndirectLight keeps per block (radiosity's point-gather caches) is tagged with it, so a
    // new block starts afresh: a pixel's value then depends on its block alone, not on which
    // thread rendered which blocks before it, nor on the blocks a partial render leaves out.
    uint64_t block = 0;
    std::shared_ptr<void> block_scratch;
    const void* block_scratch_owner = nullptr;
    uint64_t block_scratch_block = 0;

    double uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }

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
        rng.seed(uint32_t(1 + h % 2147483646u));  // minstd's seeds: 1 .. 2^31 - 2
    }
};

}  // namespace lumen::render

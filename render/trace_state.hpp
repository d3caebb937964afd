// Per-thread mutable state of the tracer: counters, the random source for area-light jitter
// and crand, and scratch space reused across rays (so tracing never allocates per ray).
#pragma once
#include <cstdint>
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

    double uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); }
};

}  // namespace lumen::render

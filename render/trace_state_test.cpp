#include "render/trace_state.hpp"

#include <random>

#include <gtest/gtest.h>

namespace lumen::render {
namespace {

// Jitter and crand draw from UniformSource: it must give std::minstd_rand's numbers through
// std::uniform_real_distribution<double>(0, 1), so renders stay as they were.
TEST(UniformSource, DrawsWhatTheStandardDistributionDrawsFromMinstd) {
    for (uint32_t seed : {1u, 2u, 12345u, 48271u, 2147483645u, 2147483646u, 0u, 2147483647u}) {
        std::minstd_rand reference(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        UniformSource source(seed);
        for (int i = 0; i < 200000; ++i) {
            const double expected = unit(reference);
            const double got = source();
            ASSERT_EQ(got, expected) << "seed " << seed << " draw " << i;
            ASSERT_GE(got, 0.0);
            ASSERT_LT(got, 1.0);
        }
    }
}

TEST(UniformSource, ReseedingRestartsTheSequence) {
    ThreadState a, b;
    a.reseed(3.25, 7.5);
    const double first = a.uniform(), second = a.uniform();
    b.uniform();  // b's own numbers before the reseed do not matter
    b.reseed(3.25, 7.5);
    EXPECT_EQ(b.uniform(), first);
    EXPECT_EQ(b.uniform(), second);
    a.reseed(3.25, 7.75);
    EXPECT_NE(a.uniform(), first);
}

}  // namespace
}  // namespace lumen::render

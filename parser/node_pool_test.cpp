// The node pool (node_pool.hpp): distinct slots, freed slots reused, safe from several threads.
#include <gtest/gtest.h>

#include "base/sanitizers.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include "parser/ast.hpp"

namespace lumen::ast {
namespace {

TEST(NodePool, SlotsAreDistinctAndHoldTheirNodes) {
    std::vector<NodePtr> nodes;
    for (int i = 0; i < 50000; ++i) {  // more than one 2 MiB slab
        nodes.push_back(std::make_unique<Node>(Kind::Number, SourceLoc{}));
        nodes.back()->number = i;
        nodes.back()->text = std::string(i % 40, 'a');  // long strings live on the heap
    }
    std::vector<uintptr_t> at;
    for (const NodePtr& n : nodes) at.push_back(reinterpret_cast<uintptr_t>(n.get()));
    std::sort(at.begin(), at.end());
    for (size_t i = 1; i < at.size(); ++i) ASSERT_GE(at[i] - at[i - 1], sizeof(Node));
    for (int i = 0; i < 50000; ++i) {
        ASSERT_EQ(nodes[i]->number, i);
        ASSERT_EQ(nodes[i]->text.size(), size_t(i % 40));
        ASSERT_EQ(reinterpret_cast<uintptr_t>(nodes[i].get()) % alignof(Node), 0u);
    }
}

TEST(NodePool, FreedSlotsAreReused) {
#if LUMEN_ASAN
    GTEST_SKIP() << "AddressSanitizer builds allocate nodes from the heap";
#endif
    auto first = std::make_unique<Node>(Kind::Ident, SourceLoc{});
    const Node* slot = first.get();
    first.reset();
    auto second = std::make_unique<Node>(Kind::Ident, SourceLoc{});
    EXPECT_EQ(second.get(), slot);
}

TEST(NodePool, ThreadsShareThePoolSafely) {
    // Each thread makes and frees nodes; the ones it keeps stay alive until both are done.
    auto churn = [](int seed, std::vector<NodePtr>& live) {
        for (int i = 0; i < 20000; ++i) {
            live.push_back(std::make_unique<Node>(Kind::Number, SourceLoc{}));
            live.back()->number = seed * 100000 + i;
            if (i % 3 == 0) live.erase(live.begin() + std::ptrdiff_t((i * 7919) % live.size()));
        }
    };
    std::vector<NodePtr> a, b;
    std::thread ta(churn, 1, std::ref(a)), tb(churn, 2, std::ref(b));
    ta.join();
    tb.join();
    std::vector<uintptr_t> at;
    for (const auto* live : {&a, &b})
        for (const NodePtr& n : *live) {
            EXPECT_EQ(int(n->number) / 100000, live == &a ? 1 : 2);
            at.push_back(reinterpret_cast<uintptr_t>(n.get()));
        }
    // No slot was handed to both threads.
    std::sort(at.begin(), at.end());
    EXPECT_EQ(std::adjacent_find(at.begin(), at.end()), at.end());
}

}  // namespace
}  // namespace lumen::ast

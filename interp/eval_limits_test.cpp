// Evaluation limits (interp/budget.hpp): runaway scenes end with a located error naming the
// limit, quickly and without exhausting memory.
#include "interp/eval_test_support.hpp"
#include "base/stop_request.hpp"

namespace lumen::interp::testing {
namespace {

using LimitsTest = EvalTest;

TEST_F(LimitsTest, DoublingAStringStopsAtTheStringLimit) {
    options.max_string_length = 1 << 20;
    EXPECT_EQ(error_of("#declare S = \"x\";\n#while (1) #declare S = concat(S, S); #end\n"),
              "test.pov:2:25: error: string of 2097152 bytes exceeds the limit of 1 MiB per string "
              "(Max_String_Length)");
}

TEST_F(LimitsTest, DefaultStringLimitStopsTheDoublingLoop) {
    const std::string e = error_of("#declare S = \"x\";\n#while (1) #declare S = concat(S, S); #end\n");
    EXPECT_EQ(e.rfind("test.pov:2:25: error: string of 33554432 bytes exceeds the limit of 16 MiB", 0), 0u) << e;
}

TEST_F(LimitsTest, ArraysAreBounded) {
    options.max_array_elements = 1000;
    EXPECT_EQ(error_of("#declare A = array[10][101];"),
              "test.pov:1:24: error: array of 1010 elements exceeds the limit of 1000 per array "
              "(Max_Array_Elements)");
    EXPECT_EQ(error_of("#declare B = array[1000];"), "");
}

TEST_F(LimitsTest, HeapLimitStopsArraysKeptInALoop) {
    options.max_memory = Budget::heap_in_use() + (size_t(64) << 20);
    const std::string e = error_of(
        "#declare A = array[1000];\n"
        "#declare I = 0;\n"
        "#while (I < 1000) #declare A[I] = array[100000]; #declare I = I + 1; #end\n");
    EXPECT_EQ(e.rfind("test.pov:3:35: error: evaluating the scene needs more than", 0), 0u) << e;
    EXPECT_NE(e.find("(limit Max_Eval_Memory;"), std::string::npos) << e;
}

TEST_F(LimitsTest, ExponentialRecursionStopsAtTheStepLimit) {
    options.max_steps = 50000;
    EXPECT_EQ(error_of("#macro M(N) #if (N > 0) M(N - 1) M(N - 1) #end #end\nM(100)\n"),
              "test.pov:1:25: error: the scene took more than 50000 evaluation steps (loop iterations "
              "and macro/function calls; limit Max_Eval_Steps): an endless loop or recursion?");
}

TEST_F(LimitsTest, StepsOfNestedLoopsAddUp) {
    options.max_steps = 5000;
    EXPECT_EQ(error_of("#for (I, 1, 100) #for (J, 1, 100) #end #end").rfind("test.pov:1:", 0), 0u);
    EXPECT_GT(evaluator().budget.steps(), 5000);
}

TEST_F(LimitsTest, StopRequestEndsAnEndlessLoop) {
    request_stop(2);
    EXPECT_THROW(run("#while (1) #end"), Interrupted);
    clear_stop_request();
}

}  // namespace
}  // namespace lumen::interp::testing

// The function VM on hand-built programs: control flow, POV-Ray's comparison and min/max rules
// for NaN, sum/prod loops, calls, transforms and externals through a host.
#include "function/vm.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "function/register_code.hpp"

namespace lumen::fn {
namespace {

Instr op(Op o, uint32_t a = 0, uint16_t b = 0, uint8_t c = 0) { return {o, c, b, a}; }

double run1(const Program& p, double x, double y = 0, double z = 0) {
    const double args[3] = {x, y, z};
    return evaluate(p, args);
}

TEST(FunctionVm, ComparisonsFollowPovRayForNaN) {
    // x OP y with NaN: <, <=, = give 0; !=, >, >= give 1 ("not less", "not equal").
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::pair<Op, double> cases[] = {{Op::Lt, 0}, {Op::Le, 0}, {Op::Eq, 0},
                                           {Op::Ne, 1}, {Op::Gt, 1}, {Op::Ge, 1}};
    for (const auto& [o, want] : cases) {
        Program p;
        p.code = {op(Op::Arg, 0), op(Op::Arg, 1), op(o)};
        EXPECT_EQ(run1(p, nan, 1), want) << int(o);
        EXPECT_EQ(run1(p, 1, nan), want) << int(o);
    }
}

TEST(FunctionVm, MinAndMaxKeepTheNewArgumentUnlessItIsNotSmaller) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Program mn, mx;
    mn.code = {op(Op::Arg, 0), op(Op::Arg, 1), op(Op::Min)};
    mx.code = {op(Op::Arg, 0), op(Op::Arg, 1), op(Op::Max)};
    EXPECT_EQ(run1(mn, nan, 5), 5);  // min(NaN, 5) = 5
    EXPECT_TRUE(std::isnan(run1(mn, 5, nan)));
    EXPECT_EQ(run1(mx, 5, nan), 5);  // max(5, NaN) = 5
    EXPECT_TRUE(std::isnan(run1(mx, nan, 5)));
    EXPECT_EQ(run1(mn, 2, 3), 2);
    EXPECT_EQ(run1(mx, 2, 3), 3);
}

TEST(FunctionVm, SelectRunsOnlyTheChosenBranch) {
    // select(x, 10, 1/0 would be inf) as jumps: x < 0 -> 10 else y.
    Program p;
    p.consts = {10};
    p.code = {op(Op::Arg, 0), op(Op::JumpIfNotNeg, 4), op(Op::Const, 0), op(Op::Jump, 5),
              op(Op::Arg, 1)};
    EXPECT_EQ(run1(p, -1, 7), 10);
    EXPECT_EQ(run1(p, 0, 7), 7);
    EXPECT_EQ(run1(p, std::nan(""), 7), 7);  // NaN takes the last branch
}

TEST(FunctionVm, SumLoopsWhileTheCounterIsAtMostTheLimit) {
    // sum(i, 0.5, x, i): locals 0 = i, 1 = limit, 2 = sum.
    Program p;
    p.consts = {0.5, 0, 1};
    p.code = {op(Op::Const, 0), op(Op::SetLocal, 0), op(Op::Arg, 0), op(Op::SetLocal, 1),
              op(Op::Const, 1), op(Op::SetLocal, 2),
              /*6*/ op(Op::Local, 0), op(Op::Local, 1), op(Op::JumpIfGreater, 18),
              op(Op::Local, 2), op(Op::Local, 0), op(Op::Add), op(Op::SetLocal, 2),
              op(Op::Local, 0), op(Op::Const, 2), op(Op::Add), op(Op::SetLocal, 0),
              op(Op::Jump, 6),
              /*18*/ op(Op::Local, 2)};
    EXPECT_EQ(run1(p, 3), 4.5);  // 0.5 + 1.5 + 2.5
    EXPECT_EQ(run1(p, 0), 0);    // empty
}

// The register form (lower.cpp) reads constants beyond the frame's share where they are used,
// and moves a local's pending value aside before the local is set again.
TEST(FunctionVm, ConstantsBeyondTheFrameAndLocalsSetAgain) {
    Program p;
    for (int i = 0; i < kFrameConsts + 40; ++i) p.consts.push_back(i * 0.25);
    const uint32_t far = kFrameConsts + 30;  // 7.5 + kFrameConsts / 4
    p.code = {op(Op::Arg, 0), op(Op::Arg, 1), op(Op::Add), op(Op::AddConst, far),
              op(Op::Const, far), op(Op::Mul)};
    EXPECT_EQ(run1(p, 1, 2), (3 + far * 0.25) * (far * 0.25));

    // locals[0] = x; push it; locals[0] = y; push it: x - y, not y - y.
    Program q;
    q.code = {op(Op::Arg, 0), op(Op::SetLocal, 0), op(Op::Local, 0), op(Op::Arg, 1),
              op(Op::SetLocal, 0), op(Op::Local, 0), op(Op::Sub)};
    EXPECT_EQ(run1(q, 5, 7), -2);
}

TEST(FunctionVm, CallsTransformsAndExternals) {
    auto square = std::make_shared<Program>();
    square->params = 1;
    square->code = {op(Op::Arg, 0), op(Op::Arg, 0), op(Op::Mul)};
    Program p;
    p.callees = {square};
    p.code = {op(Op::Arg, 0), op(Op::Call, 0, 1), op(Op::Arg, 1), op(Op::Add)};
    EXPECT_EQ(run1(p, 3, 1), 10);

    // A 3 x 4 matrix: scale 2 then translate x; member 0 (x) and the caller's component.
    Program t;
    t.consts = {2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2, 0};
    t.components = 3;
    t.code = {op(Op::Arg, 0), op(Op::Arg, 1), op(Op::Arg, 2), op(Op::Transform, 0, 3, kMemberAsked)};
    const double xyz[3] = {1, 2, 3};
    EXPECT_EQ(evaluate(t, xyz, {}, 0), 3);
    EXPECT_EQ(evaluate(t, xyz, {}, 2), 6);

    struct Grey final : Host {
        void evaluate(const External&, const double* v, double* out) const override {
            for (int i = 0; i < 5; ++i) out[i] = v[0] * (i + 1);
        }
    } host;
    Program e;
    e.externals.resize(1);
    e.needs_host = true;
    e.code = {op(Op::Arg, 0), op(Op::Arg, 1), op(Op::Arg, 2), op(Op::External, 0, 3, kMemberGray)};
    Context c;
    c.host = &host;
    EXPECT_DOUBLE_EQ(evaluate(e, xyz, c), 0.297 * 1 + 0.589 * 2 + 0.114 * 3);
    EXPECT_TRUE(std::isnan(evaluate(e, xyz)));  // no host: NaN, never a crash
}

}  // namespace
}  // namespace lumen::fn

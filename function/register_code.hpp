// The form the VM runs (vm.cpp): a program's stack code (program.hpp) lowered once
// (lower.cpp) to instructions over one frame of numbered registers, so that an operand that is
// an argument, a constant or a local is read where it lies instead of being pushed first.
// `x * 0.7` is one instruction instead of two; the stack's slots become registers too, so the
// operations, their operands and their order are the stack code's and results never differ.
//
// A frame is [constants | arguments | locals | stack slots]: a run copies the constants (the
// first kFrameConsts of them) and its arguments in, and everything else is written before it
// is read.
#pragma once
#include <cstdint>
#include <vector>

#include "function/program.hpp"

namespace lumen::fn {

// Constants beyond this many are loaded by LoadConst where they are used, so that a frame
// stays small however many constants a program has.
inline constexpr int kFrameConsts = 128;
// The most registers a frame may have: the constants, kMaxParams arguments, kMaxLocals and
// kMaxStack slots fit.
inline constexpr int kMaxFrame = 512;

// The operations, in one list that makes both the enum and the VM's dispatch table (vm.cpp).
#define LUMEN_REGISTER_OPS(X)                                                              \
    X(Move)           /* r[d] = r[s] */                                                    \
    X(LoadConst)      /* r[d] = consts[a] */                                               \
    X(Add) X(Sub) X(Mul) X(Div) /* r[d] = r[s] op r[t] */                                   \
    X(Neg)            /* r[d] = -r[s] */                                                   \
    X(Lt) X(Le) X(Eq) X(Ne) X(Ge) X(Gt) /* as Op's */                                       \
    X(And) X(Or)                                                                           \
    X(Math1)          /* r[d] = math1(a, r[s]) */                                          \
    X(Math2)          /* r[d] = math2(a, r[s], r[t]) */                                    \
    X(Min) X(Max)     /* r[d] = POV's min/max(r[s], r[t]) */                               \
    X(Jump)           /* pc = a */                                                         \
    X(JumpIfNotNeg)   /* unless r[s] < 0, pc = a */                                        \
    X(JumpIfNotZero)  /* unless r[s] == 0, pc = a */                                       \
    X(JumpIfGreater)  /* unless r[s] <= r[t], pc = a */                                    \
    X(Internal)       /* r[d] = internal a at r[s ...] */                                  \
    X(Call)           /* r[d] = callees[a] at r[s ...], component c */                     \
    X(External)       /* r[d] = member c of externals[a] at r[s], r[s + 1], r[s + 2] */    \
    X(Transform)      /* r[d] = member c of the matrix at consts[a] times r[s ...] */      \
    X(Spline)         /* r[d] = member c of splines[a] at r[s] */                          \
    X(Return)         /* the result is r[s] (0 when a is 1: the stack was empty) */

enum class ROp : uint8_t {
#define LUMEN_ROP_ENUM(name) name,
    LUMEN_REGISTER_OPS(LUMEN_ROP_ENUM)
#undef LUMEN_ROP_ENUM
};

struct RInstr {
    ROp op;
    uint8_t c = 0;
    uint16_t d = 0, s = 0, t = 0;
    uint32_t a = 0;
};

struct RegisterCode {
    std::vector<RInstr> code;
    int frame_consts = 0;  // constants copied into r[0 ..)
    int args = 0;          // arguments copied into r[frame_consts ..)
    int frame = 0;         // registers in all
};

RegisterCode lower(const Program& program);

}  // namespace lumen::fn

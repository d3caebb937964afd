// A compiled `function { ... }`: plain data, made once where the function is declared (the
// interpreter's compile_function.cpp) with every captured identifier folded in, and run by
// vm.hpp from the interpreter (`F(1, 2, 3)`) and from every render thread (isosurfaces,
// function patterns) alike. It sits below both, as noise/ does.
//
// The code is a stack machine: each instruction pops its operands and pushes its result.
// POV-Ray's function language has no assignments; numbered local slots hold sum()/prod()'s
// counters and the compiler's temporaries (pow's base, select's test), at most kMaxLocals.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "function/spline.hpp"

namespace lumen::fn {

enum class Op : uint8_t {
    Const,      // push consts[a]
    Arg,        // push args[a]
    Local,      // push locals[a]
    SetLocal,   // locals[a] = pop
    Add, Sub, Mul, Div, Neg,
    AddConst, SubConst, MulConst,  // top op= consts[a] (an operator with a constant right side)
    Lt, Le, Eq, Ne, Ge, Gt,  // 1 or 0; exact (no SDL tolerance); NaN: Ne, Gt, Ge give 1
    And, Or,                 // (a != 0) and/or (b != 0)
    Math1,      // push math1(a, pop): sin, cos, ... (Math1 below)
    Math2,      // b = pop, a = pop: push math2(a, b)
    Min, Max,   // pop 2, push POV's min/max (see vm.cpp)
    Jump,       // pc = a
    JumpIfNotNeg,   // pop v: unless v < 0, pc = a  (select's first test; NaN jumps)
    JumpIfNotZero,  // pop v: unless v == 0, pc = a
    JumpIfGreater,  // pop y, pop x: unless x <= y, pc = a (the sum/prod loop test)
    Internal,   // pop b arguments (x, y, z, then parameters), push internal function a
    Call,       // pop b arguments, push callees[a]'s result (component c for vectors)
    External,   // pop x, y, z: push member c of externals[a] there (Host)
    Transform,  // pop x, y, z: push member c of the 3 x 4 matrix at consts[a..a+11] times them
    Spline,     // pop t: push member c of splines[a] at t
};

// Members of a vector result: 0..4 the components (x/red .. transmit), then these.
inline constexpr uint8_t kMemberGray = 5;  // 0.297 c0 + 0.589 c1 + 0.114 c2
inline constexpr uint8_t kMemberHf = 6;    // (c0 + c1 / 255) x 0.996093
inline constexpr uint8_t kMemberAsked = 255;  // the component the caller asks for

// What the VM cannot evaluate by itself: a pigment function's colour or a pattern function's
// value, computed by the Host the run is given (the renderer's). The payload is the scene's
// pigment (a pattern function's pattern is that pigment's), owned here and typed by the host.
struct External {
    enum class Kind : uint8_t { Pigment, Pattern };
    Kind kind = Kind::Pigment;
    std::shared_ptr<const void> payload;
    uint64_t content = 0;  // the payload's content hash, so that programs hash by content
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("kind", s.kind), f("content", s.content);
    }
};

// Math1's functions, in POV-Ray's order of its allowed one-argument calls.
enum class Math1 : uint8_t {
    Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Asinh, Acosh, Atanh, Abs, Floor, Ceil,
    Sqrt, Exp, Ln, Log, Int, Radians, Degrees
};
enum class Math2 : uint8_t { Atan2, Pow, Mod, Div };

struct Instr {
    Op op;
    uint8_t c = 0;   // Call: the component of a vector result
    uint16_t b = 0;  // argument count (Internal, Call)
    uint32_t a = 0;  // operand: constant, argument, local, jump target, function number
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("op", s.op), f("c", s.c), f("b", s.b), f("a", s.a);
    }
};

struct Program;
struct RegisterCode;

// A program's register form (register_code.hpp), lowered on its first run and kept. Copies
// start without it. Two threads' first runs may both lower; one result is kept.
class LoweredCode {
public:
    LoweredCode() = default;
    LoweredCode(const LoweredCode&) {}
    LoweredCode& operator=(const LoweredCode&) {
        reset();
        return *this;
    }
    ~LoweredCode() { reset(); }
    const RegisterCode& get(const Program& program) const;

private:
    void reset();
    mutable std::atomic<const RegisterCode*> code_{nullptr};
};

struct Program {
    std::vector<Instr> code;
    std::vector<double> consts;
    int params = 3;     // arguments expected (x, y, z when the function names none)
    int components = 1; // results (1: a float function)
    std::vector<std::shared_ptr<const Program>> callees;  // functions it calls, as they were
    std::vector<External> externals;
    std::vector<std::shared_ptr<const Spline>> splines;
    bool needs_host = false;  // it or a callee has externals
    LoweredCode lowered;      // made from the fields above, which must not change after a run
    template <class Self, class F> static void fields(Self& s, F&& f) {
        f("code", s.code), f("consts", s.consts), f("params", s.params), f("callees", s.callees),
            f("externals", s.externals), f("splines", s.splines);
    }
};

using ProgramPtr = std::shared_ptr<const Program>;

}  // namespace lumen::fn

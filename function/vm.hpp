// Runs a compiled function (program.hpp). Safe from any number of threads at once: the
// program is read-only and a call keeps its stack in a fixed array on the C++ stack, so no
// call allocates or locks.
#pragma once
#include <span>

#include "function/program.hpp"

namespace lumen::fn {

// Evaluates externals (program.hpp): the renderer implements it; the interpreter is handed one.
class Host {
public:
    virtual ~Host() = default;
    // The external's components at (x, y, z): 5 for a pigment (r, g, b, f, t, as floats
    // give them), 1 for a pattern.
    virtual void evaluate(const External& e, const double* xyz, double* out) const = 0;
};

// What a run may depend on besides its arguments.
struct Context {
    int noise_generator = 2;     // the scene's global_settings noise_generator (f_noise3d)
    const Host* host = nullptr;  // needed by programs with needs_host; else externals are NaN
};

// The deepest chain of calls between compiled functions (POV-Ray's own limit is 1024).
inline constexpr int kMaxCallDepth = 1024;
// The deepest stack one program may need, and its locals (the compiler refuses more).
inline constexpr int kMaxStack = 256;
inline constexpr int kMaxLocals = 16;
// The most parameters a function may name (POV-Ray's limit: 57 are "Missing {").
inline constexpr int kMaxParams = 56;

// The function's value at `args` (program.params of them; the compiler checks counts). For a
// vector function, component `component`.
double evaluate(const Program& program, std::span<const double> args, const Context& context = {},
                int component = 0);

}  // namespace lumen::fn

// POV-Ray's internal functions: `function { internal(N) }`, which functions.inc declares as
// f_algbr_cyl1 ... f_noise_generator (N = 0 .. 78), with POV-Ray 3.7's formulas. Each takes
// x, y, z and then its own parameters.
#pragma once

namespace lumen::fn {

inline constexpr int kInternalCount = 79;

struct InternalInfo {
    const char* name;  // functions.inc's name without "f_" ("algbr_cyl1", ...)
    int params;        // parameters after x, y, z
};

// n in [0, kInternalCount).
const InternalInfo& internal_info(int n);

// Internal function n at args = {x, y, z, p1, ..., p_params}. `noise_generator` is the
// scene's global_settings noise_generator (1..3), which f_noise3d (76) uses. Never throws;
// may return inf or NaN as POV does.
double internal(int n, const double* args, int noise_generator);

}  // namespace lumen::fn

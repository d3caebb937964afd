// POV-Ray's anti-aliasing jitter: a deterministic hash of the
// sample position picks one of 256 fixed offsets, so jittered renders are reproducible and
// identical to POV-Ray's.
#pragma once
#include <array>

namespace lumen::render {

// The 256 offsets in [−0.5, 0.5), measured from POV-Ray's renders (render/jitter_table.cpp).
const std::array<float, 256>& jitter_table();

// Which table entry the sample position (x, y), in pixel units, reads:
// H[(H[int(x·mul_x) & 4095] XOR int(y·mul_y)) & 4095] & 255, with H a fixed permutation of
// 0..4095. jx uses (1021, 1019), jy (1019, 1021).
int jitter_index(double x, double y, int mul_x, int mul_y);

// H[i & 4095]: the permutation itself (focal blur picks its sub-pixel offsets with it).
int jitter_hash(int i);

// The jitter (jx, jy) ∈ [−0.5, 0.5)² of the sample position (x, y); the caller scales it by
// the jitter amount and the sample spacing.
void jitter2d(double x, double y, double& jx, double& jy);

}  // namespace lumen::render

#include "render/radiosity/irradiance_cache.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <glm/geometric.hpp>

namespace lumen::render::radiosity {

namespace {

// How far past the cache error a record still contributes to the average
// (faded).
constexpr double kFade = 3;

} // namespace

IrradianceCache::IrradianceCache(const CacheSettings &settings,
                                 const glm::dvec3 &extent)
    : s_(settings) {
  const double reach = kFade * s_.error * s_.max_reuse *
                       std::max(1.0, glm::length(extent - s_.camera));
  cell_ = std::max(reach / 2, 1e-6);
}

IrradianceCache::Cell IrradianceCache::cell_of(const glm::dvec3 &p,
                                               int level) const {
  const double size = std::ldexp(cell_, level);
  return {(long long)std::floor(p.x / size), (long long)std::floor(p.y / size),
          (long long)std::floor(p.z / size), level};
}

bool IrradianceCache::lookup(const glm::dvec3 &p, const glm::dvec3 &n,
                             glm::dvec3 &out) const {
  std::shared_lock lock(mutex_);
  glm::dvec3 sum(0);
  double wsum = 0;
  bool covered = false;
  const double a = s_.error;
  for (int level = 0; level < 64; ++level) {
    if (!(levels_ >> level & 1))
      continue;
    const auto it = grid_.find(cell_of(p, level));
    if (it == grid_.end())
      continue;
    for (const Entry &entry : it->second) {
      const glm::dvec3 d = p - entry.position;
      if (glm::dot(d, d) >= entry.reach2)
        continue; // e >= |d| / R >= 3a
      const Record &c = records_[entry.index];
      const double nd = glm::dot(n, c.normal);
      if (nd < 0.9)
        continue;
      if (std::fabs(glm::dot(d, n)) > 0.1 * c.radius)
        continue; // another surface
      const double e =
          glm::length(d) / c.radius + std::sqrt(std::max(0.0, 1 - nd));
      if (e >= kFade * a)
        continue;
      covered = covered || e < a;
      const double w = (1 - e / (kFade * a)) * (1 - e / (kFade * a));
      // Extrapolated by the gradients, each channel kept within [G / 2, 2 G]: a gradient
      // from a few noisy strata must not overshoot either way (with [0, 2 G] a lone record
      // of a render block extrapolated a lit wall of rad_def_test_36.pov to black).
      const glm::dvec3 turn = glm::cross(c.normal, n);
      glm::dvec3 value = c.G;
      for (int ch = 0; ch < 3; ++ch)
        value[ch] = std::clamp(c.G[ch] + glm::dot(d, c.gradients.translation[ch]) +
                                   glm::dot(turn, c.gradients.rotation[ch]),
                               0.5 * c.G[ch], 2 * c.G[ch]);
      sum += w * value;
      wsum += w;
    }
  }
  if (!covered || wsum <= 0)
    return false;
  out = sum / wsum;
  return true;
}

void IrradianceCache::insert(const glm::dvec3 &p, const glm::dvec3 &n,
                             const glm::dvec3 &G, double harmonic_distance,
                             const IrradianceGradients &gradients) {
  const double camera = glm::length(p - s_.camera);
  Record c{p, n, G,
           std::max(std::clamp(harmonic_distance, s_.min_reuse * camera,
                               s_.max_reuse * camera),
                    1e-9),
           gradients};
  std::unique_lock lock(mutex_);
  const uint32_t index = uint32_t(records_.size());
  records_.push_back(c);
  const double r = kFade * c.radius * s_.error;
  const int level =
      std::clamp(int(std::ceil(std::log2(std::max(r / cell_, 1.0)))), 0, 63);
  levels_ |= uint64_t(1) << level;
  const Cell lo = cell_of(c.position - glm::dvec3(r), level),
             hi = cell_of(c.position + glm::dvec3(r), level);
  for (long long x = lo[0]; x <= hi[0]; ++x)
    for (long long y = lo[1]; y <= hi[1]; ++y)
      for (long long z = lo[2]; z <= hi[2]; ++z)
        grid_[{x, y, z, level}].push_back({c.position, r * r, index});
}

size_t IrradianceCache::size() const {
  std::shared_lock lock(mutex_);
  return records_.size();
}

} // namespace lumen::render::radiosity

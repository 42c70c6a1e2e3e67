// The arithmetic of texture filtering, shared by the texture unit's sampling paths: texel
// coordinate wrapping and flooring, Morton (twiddled) address steps, and level-of-detail
// selection from the screen-space footprint.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

#include "sim/texture.h"

namespace skinsim::sim::filtering {

inline int wrap_coord(int i, int size, Wrap wrap) {
  if (static_cast<unsigned>(i) < static_cast<unsigned>(size)) return i;  // the common case
  if (wrap == Wrap::kRepeat) {
    if ((size & (size - 1)) == 0) return i & (size - 1);
    const int m = i % size;
    return m < 0 ? m + size : m;
  }
  return std::clamp(i, 0, size - 1);
}

// floor(v) as ints and the fractions v - floor(v) of both texel coordinates at once, in one
// SIMD register (GCC/Clang vector extensions) and without a libm call: the sample path's
// longest dependency chain. Coordinates are clamped to +-2^30 texels first (NaN to
// -2^30), far beyond any texture.
struct FloorSplit {
  int x, y;
  float fraction_x, fraction_y;
};
inline FloorSplit floor_split(glm::vec2 v) {
  using Float4 = float __attribute__((vector_size(16)));
  using Int4 = std::int32_t __attribute__((vector_size(16)));
  constexpr float kLimit = 1073741824.0f;
  const Float4 limit = {kLimit, kLimit, kLimit, kLimit};
  Float4 p = {v.x, v.y, 0.0f, 0.0f};
  p = p > -limit ? (p < limit ? p : limit) : -limit;    // NaN fails both: -kLimit
  Int4 whole = __builtin_convertvector(p, Int4);        // truncates toward zero
  whole += p < __builtin_convertvector(whole, Float4);  // true is -1: one down when v < 0
  const Float4 fraction = p - __builtin_convertvector(whole, Float4);
  return {whole[0], whole[1], fraction[0], fraction[1]};
}

// Morton code of x + 1 from the Morton code of x (x in the even bits): filling the odd
// bits with ones makes the carry ripple across them.
inline std::uint64_t morton_increment(std::uint64_t spread) {
  constexpr std::uint64_t kEven = 0x5555555555555555ull;
  return ((spread | ~kEven) + 1) & kEven;
}

inline std::uint64_t spread_next(std::uint64_t spread_prev, int prev, int next) {
  return next == prev + 1 ? morton_increment(spread_prev)
                          : morton_spread(static_cast<std::uint32_t>(next));
}

// Squared footprint length rho^2 in texels (OpenGL ES 2.0 spec 3.7.7: rho = max of the
// two screen-axis footprint lengths); lambda = log2(rho).
inline float footprint_rho2(float du_dx, float dv_dx, float du_dy, float dv_dy) {
  return std::max(du_dx * du_dx + dv_dx * dv_dx, du_dy * du_dy + dv_dy * dv_dy);
}

inline float lod_from_rho2(float rho2) {
  return rho2 > 0.0f ? 0.5f * std::log2(rho2) : -1000.0f;
}

// The level a nearest-mip sample uses, round(lambda) clamped to the chain, found from the
// exponent of rho^2 alone: with rho^2 = m 2^e (m in [1,2)), round(e/2 + log2(m)/2) =
// floor((e+1)/2). Exact, and no logarithm on the common path.
inline int nearest_level(float rho2, int max_level) {
  if (max_level == 0 || !(rho2 >= 1.0f)) return 0;  // also catches NaN
  if (std::isinf(rho2)) return max_level;
  const int e = std::ilogb(rho2);
  return std::min((e + 1) / 2, max_level);
}

}  // namespace skinsim::sim::filtering

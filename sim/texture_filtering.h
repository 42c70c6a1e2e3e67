// The arithmetic of texture filtering, shared by the texture unit's sampling paths: texel
// coordinate wrapping and flooring, Morton (twiddled) address steps, and level-of-detail
// selection from the screen-space footprint.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

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

// floor(v) as an int and the fraction v - floor(v), without a libm call on the sample
// path. Coordinates are clamped to +-2^30 texels first (NaN to 0), far beyond any texture.
struct FloorSplit {
  int whole;
  float fraction;
};
inline FloorSplit floor_split(float v) {
  constexpr float kLimit = 1073741824.0f;
  v = v > -kLimit ? (v < kLimit ? v : kLimit) : -kLimit;  // NaN fails both: -kLimit
  int i = static_cast<int>(v);  // truncates toward zero
  i -= v < static_cast<float>(i) ? 1 : 0;
  return {i, v - static_cast<float>(i)};
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

inline float lod_from_rho2(float rho2) { return rho2 > 0.0f ? 0.5f * std::log2(rho2) : -1000.0f; }

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

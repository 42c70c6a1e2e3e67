#include "sim/texture_footprints.h"

#include <algorithm>
#include <cstring>

#include "sim/texture_filtering.h"
#include "util/simd_dispatch.h"

// Eight-lane vectors live only inside the AVX2 function and the always-inlined kernel: none is
// passed between functions (see quality/float_lanes.h).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace skinsim::sim {

namespace {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Uint4 = std::uint32_t __attribute__((vector_size(16)));
using Float8 = float __attribute__((vector_size(32)));
using Int8 = std::int32_t __attribute__((vector_size(32)));
using Uint8 = std::uint32_t __attribute__((vector_size(32)));

// morton_spread of each lane's low 16 bits: the bits moved to the even positions.
template <class U>
[[gnu::always_inline]] inline U spread_lanes(U s) {
  s &= 0xFFFFu;
  s = (s | (s << 8)) & 0x00FF00FFu;
  s = (s | (s << 4)) & 0x0F0F0F0Fu;
  s = (s | (s << 2)) & 0x33333333u;
  s = (s | (s << 1)) & 0x55555555u;
  return s;
}

// Footprints first .. first + lanes - 1 (those at or beyond count are computed from (0, 0) and
// not used).
template <class F, class I, class U>
[[gnu::always_inline]] inline void footprints(const float* u, const float* v, int first, int count,
                                              const LevelView& level, Wrap wrap,
                                              std::uint32_t level_base, std::uint32_t texel_bytes,
                                              std::uint32_t line_shift, FootprintLanes& out) {
  constexpr int kLanes = static_cast<int>(sizeof(F) / sizeof(float));
  F pu{}, pv{};
  std::memcpy(&pu, u + first, sizeof(F));
  std::memcpy(&pv, v + first, sizeof(F));
  // filtering::floor_split of uv * (width, height) - 0.5, lane by lane.
  F limit{};
  limit += 1073741824.0f;
  pu = pu * static_cast<float>(level.width) - 0.5f;
  pv = pv * static_cast<float>(level.height) - 0.5f;
  pu = pu > -limit ? (pu < limit ? pu : limit) : -limit;  // NaN fails both: -limit
  pv = pv > -limit ? (pv < limit ? pv : limit) : -limit;
  I x0 = __builtin_convertvector(pu, I);  // truncates toward zero
  I y0 = __builtin_convertvector(pv, I);
  x0 += pu < __builtin_convertvector(x0, F);  // true is -1: one down below zero
  y0 += pv < __builtin_convertvector(y0, F);
  const F ax = pu - __builtin_convertvector(x0, F);
  const F ay = pv - __builtin_convertvector(y0, F);
  I x1 = x0 + 1, y1 = y0 + 1;

  // filtering::wrap_coord, needed only where a footprint leaves the level.
  const U inside = (reinterpret_cast<U>(x0) < static_cast<std::uint32_t>(level.width - 1)) &
                   (reinterpret_cast<U>(y0) < static_cast<std::uint32_t>(level.height - 1));
  bool all_inside = true;
  for (int i = 0; i < kLanes; ++i) all_inside &= first + i >= count || inside[i] != 0;
  if (!all_inside) {
    for (int i = 0; i < kLanes; ++i) {
      x0[i] = filtering::wrap_coord(x0[i], level.width, wrap);
      x1[i] = filtering::wrap_coord(x1[i], level.width, wrap);
      y0[i] = filtering::wrap_coord(y0[i], level.height, wrap);
      y1[i] = filtering::wrap_coord(y1[i], level.height, wrap);
    }
  }
  const U sx0 = spread_lanes(reinterpret_cast<U>(x0)), sx1 = spread_lanes(reinterpret_cast<U>(x1));
  const U sy0 = spread_lanes(reinterpret_cast<U>(y0)) << 1;
  const U sy1 = spread_lanes(reinterpret_cast<U>(y1)) << 1;
  const auto line = [&](U twiddled) { return (level_base + twiddled * texel_bytes) >> line_shift; };
  const auto store = [&](auto& lanes, const auto& values) {
    std::memcpy(lanes.data() + first, &values, sizeof(values));
  };
  store(out.x0, x0);
  store(out.x1, x1);
  store(out.y0, y0);
  store(out.y1, y1);
  store(out.ax, ax);
  store(out.ay, ay);
  store(out.lines[0], line(sx0 | sy0));
  store(out.lines[1], line(sx1 | sy0));
  store(out.lines[2], line(sx0 | sy1));
  store(out.lines[3], line(sx1 | sy1));
}

[[gnu::target("avx2")]] void footprints_avx2(const float* u, const float* v, int count,
                                             const LevelView& level, Wrap wrap,
                                             std::uint32_t level_base, std::uint32_t texel_bytes,
                                             std::uint32_t line_shift, FootprintLanes& out) {
  footprints<Float8, Int8, Uint8>(u, v, 0, count, level, wrap, level_base, texel_bytes, line_shift,
                                  out);
}

void footprints_sse2(const float* u, const float* v, int count, const LevelView& level, Wrap wrap,
                     std::uint32_t level_base, std::uint32_t texel_bytes, std::uint32_t line_shift,
                     FootprintLanes& out) {
  for (int first = 0; first < count; first += 4) {
    footprints<Float4, Int4, Uint4>(u, v, first, count, level, wrap, level_base, texel_bytes,
                                    line_shift, out);
  }
}

}  // namespace

void address_footprints(const float* u, const float* v, int count, const LevelView& level,
                        Wrap wrap, std::uint32_t level_base, std::uint32_t texel_bytes,
                        std::uint32_t line_shift, FootprintLanes& out) {
  if (use_avx2()) {
    footprints_avx2(u, v, count, level, wrap, level_base, texel_bytes, line_shift, out);
  } else {
    footprints_sse2(u, v, count, level, wrap, level_base, texel_bytes, line_shift, out);
  }
}

}  // namespace skinsim::sim

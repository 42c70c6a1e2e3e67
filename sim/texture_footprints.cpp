#include "sim/texture_footprints.h"

#include <cstring>

#include "sim/texture_filtering.h"
#include "util/float_lanes.h"
#include "util/simd_dispatch.h"

// Eight-lane vectors pass only between always-inlined functions (util/float_lanes.h).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace skinsim::sim {

namespace {

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
template <class V>
[[gnu::always_inline]] inline void footprints(const float* u, const float* v, int first, int count,
                                              const LevelView& level, Wrap wrap,
                                              std::uint32_t level_base, std::uint32_t texel_bytes,
                                              std::uint32_t line_shift, FootprintLanes& out) {
  using I = IntLanes<V>;
  using U = UintLanes<V>;
  // filtering::floor_split of uv * (width, height) - 0.5, lane by lane.
  const V limit = splat<V>(1073741824.0f);
  V pu = load_lanes<V>(u + first, kLanes<V>) * static_cast<float>(level.width) - 0.5f;
  V pv = load_lanes<V>(v + first, kLanes<V>) * static_cast<float>(level.height) - 0.5f;
  pu = pu > -limit ? (pu < limit ? pu : limit) : -limit;  // NaN fails both: -limit
  pv = pv > -limit ? (pv < limit ? pv : limit) : -limit;
  I x0 = floor_lanes(pu), y0 = floor_lanes(pv);
  const V ax = pu - __builtin_convertvector(x0, V);
  const V ay = pv - __builtin_convertvector(y0, V);
  I x1 = x0 + 1, y1 = y0 + 1;

  // filtering::wrap_coord, needed only where a footprint leaves the level.
  const U inside = (reinterpret_cast<U>(x0) < static_cast<std::uint32_t>(level.width - 1)) &
                   (reinterpret_cast<U>(y0) < static_cast<std::uint32_t>(level.height - 1));
  bool all_inside = true;
  for (int i = 0; i < kLanes<V>; ++i) all_inside &= first + i >= count || inside[i] != 0;
  if (!all_inside) {
    for (int i = 0; i < kLanes<V>; ++i) {
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
  footprints<Float8>(u, v, 0, count, level, wrap, level_base, texel_bytes, line_shift, out);
}

void footprints_sse2(const float* u, const float* v, int count, const LevelView& level, Wrap wrap,
                     std::uint32_t level_base, std::uint32_t texel_bytes, std::uint32_t line_shift,
                     FootprintLanes& out) {
  for (int first = 0; first < count; first += 4) {
    footprints<Float4>(u, v, first, count, level, wrap, level_base, texel_bytes, line_shift, out);
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

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
// Each lane samples a level `width` x `height` texels laid out from `level_base`.
template <class V>
[[gnu::always_inline]] inline void footprints(V u, V v, int first, int count, IntLanes<V> width,
                                              IntLanes<V> height, Wrap wrap,
                                              UintLanes<V> level_base, std::uint32_t texel_bytes,
                                              std::uint32_t line_shift, FootprintLanes& out) {
  using I = IntLanes<V>;
  using U = UintLanes<V>;
  // filtering::floor_split of uv * (width, height) - 0.5, lane by lane.
  const V limit = splat<V>(1073741824.0f);
  V pu = u * __builtin_convertvector(width, V) - 0.5f;
  V pv = v * __builtin_convertvector(height, V) - 0.5f;
  pu = pu > -limit ? (pu < limit ? pu : limit) : -limit;  // NaN fails both: -limit
  pv = pv > -limit ? (pv < limit ? pv : limit) : -limit;
  I x0 = floor_lanes(pu), y0 = floor_lanes(pv);
  const V ax = pu - __builtin_convertvector(x0, V);
  const V ay = pv - __builtin_convertvector(y0, V);
  I x1 = x0 + 1, y1 = y0 + 1;

  // filtering::wrap_coord, needed only where a footprint leaves the level.
  const U inside = (reinterpret_cast<U>(x0) < reinterpret_cast<U>(width - 1)) &
                   (reinterpret_cast<U>(y0) < reinterpret_cast<U>(height - 1));
  bool all_inside = true;
  for (int i = 0; i < kLanes<V>; ++i) all_inside &= first + i >= count || inside[i] != 0;
  if (!all_inside) {
    for (int i = 0; i < kLanes<V>; ++i) {
      x0[i] = filtering::wrap_coord(x0[i], width[i], wrap);
      x1[i] = filtering::wrap_coord(x1[i], width[i], wrap);
      y0[i] = filtering::wrap_coord(y0[i], height[i], wrap);
      y1[i] = filtering::wrap_coord(y1[i], height[i], wrap);
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
  using I = IntLanes<Float8>;
  footprints<Float8>(load_lanes<Float8>(u, 8), load_lanes<Float8>(v, 8), 0, count,
                     I{} + level.width, I{} + level.height, wrap, UintLanes<Float8>{} + level_base,
                     texel_bytes, line_shift, out);
}

void footprints_sse2(const float* u, const float* v, int count, const LevelView& level, Wrap wrap,
                     std::uint32_t level_base, std::uint32_t texel_bytes, std::uint32_t line_shift,
                     FootprintLanes& out) {
  for (int first = 0; first < count; first += 4) {
    footprints<Float4>(load_lanes<Float4>(u + first, 4), load_lanes<Float4>(v + first, 4), first,
                       count, Int4{} + level.width, Int4{} + level.height, wrap,
                       Uint4{} + level_base, texel_bytes, line_shift, out);
  }
}

// The two halves of a LevelSamples field as eight lanes.
template <class Half>
[[gnu::always_inline]] inline auto joined(const std::array<Half, 2>& halves) {
  return __builtin_shufflevector(halves[0], halves[1], 0, 1, 2, 3, 4, 5, 6, 7);
}

[[gnu::target("avx2")]] void footprints_at_levels_avx2(const LevelSamples& s, Wrap wrap,
                                                       std::uint32_t texel_bytes,
                                                       std::uint32_t line_shift,
                                                       FootprintLanes& out) {
  footprints<Float8>(joined(s.u), joined(s.v), 0, FootprintLanes::kMax, joined(s.width),
                     joined(s.height), wrap, joined(s.base), texel_bytes, line_shift, out);
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

void address_footprints(const LevelSamples& s, Wrap wrap, std::uint32_t texel_bytes,
                        std::uint32_t line_shift, FootprintLanes& out) {
  if (use_avx2()) {
    footprints_at_levels_avx2(s, wrap, texel_bytes, line_shift, out);
  } else {
    for (int half = 0; half < 2; ++half) {
      footprints<Float4>(s.u[half], s.v[half], 4 * half, FootprintLanes::kMax, s.width[half],
                         s.height[half], wrap, s.base[half], texel_bytes, line_shift, out);
    }
  }
}

}  // namespace skinsim::sim

// The bilinear footprints of up to eight samples of one texture level, addressed together in
// SIMD lanes: eight in AVX2 where the processor has it, four at a time in SSE2 otherwise
// (util/simd_dispatch.h). Each lane does what ExecTexUnit::fetch_footprint does for one
// sample, with the same IEEE operations (filtering::floor_split's flooring, wrap_coord's
// wrapping, the twiddled address as Texture2D::texel_offset gives it), so a footprint does not
// depend on which samples share its register or on the processor. The texture unit's
// per-sample path remains the reference; ExecTexUnit::sample_each serves a program's several
// reads of one texture (a blur's taps) from here.
#pragma once

#include <array>
#include <cstdint>

#include "sim/texture.h"
#include "util/float_lanes.h"

namespace skinsim::sim {

struct FootprintLanes {
  static constexpr int kMax = 8;
  // The 2x2 texels after wrapping, and the blend weights.
  std::array<int, kMax> x0, x1, y0, y1;
  std::array<float, kMax> ax, ay;
  // The cache lines of texels (x0,y0), (x1,y0), (x0,y1), (x1,y1), in that order.
  std::array<std::array<std::uint32_t, kMax>, 4> lines;
};

// Footprints of samples at (u[i], v[i]), i < count <= FootprintLanes::kMax, of one level of a
// texture laid out from `level_base` (its address in the emulated memory, below 2^32) with
// `texel_bytes` a texel; cache lines are 2^line_shift bytes. u and v hold kMax values (those
// from count on are ignored).
void address_footprints(const float* u, const float* v, int count, const LevelView& level,
                        Wrap wrap, std::uint32_t level_base, std::uint32_t texel_bytes,
                        std::uint32_t line_shift, FootprintLanes& out);

// Eight samples of one texture, each at its own level: sample i at (u, v) of a level width x
// height texels laid out from `base` (its address in the emulated memory), in lane i % 4 of
// half i / 4: the four fragments of a batch (shader_exec4_io.h), each at the levels its own
// derivatives select, both levels of a trilinear sample at once. In whole four-lane vectors,
// which a caller builds in registers: the eight-lane path loads each as written, where loading
// lanes written one by one waited for the stores (perf annotate: the loads of the
// per-lane-level array held 15% of the function's samples).
struct LevelSamples {
  std::array<Float4, 2> u, v;
  std::array<Int4, 2> width, height;
  std::array<Uint4, 2> base;
};
void address_footprints(const LevelSamples& samples, Wrap wrap, std::uint32_t texel_bytes,
                        std::uint32_t line_shift, FootprintLanes& out);

}  // namespace skinsim::sim

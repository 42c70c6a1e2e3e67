// The texture unit's per-sample path, inline because every shader's inner loop calls it:
// visible here, it is compiled into each shader program with the shader's own constants.
// Included at the end of texture_unit.h only.
#pragma once

#include <algorithm>
#include <type_traits>

#include "sim/texture_filtering.h"
#include "sim/texture_footprints.h"
#include "util/check.h"

namespace skinsim::sim {

inline const Texture2D& ExecTexUnit::texture(int binding) const {
  SKINSIM_DCHECK_INDEX(binding, kMaxTextureBindings);
  const Texture2D* t = bindings_ ? bindings_->textures[binding] : nullptr;
  if (!t) unbound(binding, "2D texture");
  return *t;
}

inline void ExecTexUnit::access_line(std::uint64_t line) {
  ++counters_->cache_line_accesses;
  lines_->add(line);
}

inline glm::vec4 ExecTexUnit::nearest(const Texture2D& tex, std::uint64_t base, int level,
                                      glm::vec2 uv) {
  const LevelView& l = tex.level(level);
  const filtering::FloorSplit f = filtering::floor_split(
      uv * glm::vec2(static_cast<float>(l.width), static_cast<float>(l.height)));
  const int x = filtering::wrap_coord(f.x, l.width, tex.sampler().wrap);
  const int y = filtering::wrap_coord(f.y, l.height, tex.sampler().wrap);
  ++counters_->texels_touched;
  access_line(lines_->line_of(base + tex.texel_offset(level, x, y)));
  return l.at(x, y);
}

inline ExecTexUnit::Footprint ExecTexUnit::fetch_footprint(const Texture2D& tex, std::uint64_t base,
                                                           int level, glm::vec2 uv) {
  const LevelView& l = tex.level(level);
  const Wrap wrap = tex.sampler().wrap;
  const filtering::FloorSplit f = filtering::floor_split(
      uv * glm::vec2(static_cast<float>(l.width), static_cast<float>(l.height)) - 0.5f);
  const Footprint fp{&l,
                     filtering::wrap_coord(f.x, l.width, wrap),
                     filtering::wrap_coord(f.x + 1, l.width, wrap),
                     filtering::wrap_coord(f.y, l.height, wrap),
                     filtering::wrap_coord(f.y + 1, l.height, wrap),
                     f.fraction_x,
                     f.fraction_y};

  // The 2x2 footprint's texel addresses in the twiddled layout, and the distinct cache lines
  // among them, recorded in footprint order (usually one: a 64-byte line holds a 4x4
  // RGBA8 block).
  const std::uint64_t level_base = base + tex.level_offset(level);
  const std::uint64_t bpp = tex.texel_bytes();
  const std::uint64_t sx0 = morton_spread(static_cast<std::uint32_t>(fp.x0));
  const std::uint64_t sy0 = morton_spread(static_cast<std::uint32_t>(fp.y0)) << 1;
  const std::uint64_t sx1 = filtering::spread_next(sx0, fp.x0, fp.x1);
  const std::uint64_t sy1 = filtering::spread_next(sy0 >> 1, fp.y0, fp.y1) << 1;
  const std::uint64_t a00 = level_base + (sx0 | sy0) * bpp, a10 = level_base + (sx1 | sy0) * bpp;
  const std::uint64_t a01 = level_base + (sx0 | sy1) * bpp, a11 = level_base + (sx1 | sy1) * bpp;
  record_footprint(lines_->line_of(a00), lines_->line_of(a10), lines_->line_of(a01),
                   lines_->line_of(a11));
  return fp;
}

inline void ExecTexUnit::record_footprint(std::uint64_t l00, std::uint64_t l10, std::uint64_t l01,
                                          std::uint64_t l11) {
  counters_->texels_touched += 4;
  access_line(l00);
  if (l10 != l00) access_line(l10);
  if (l01 != l00 && l01 != l10) access_line(l01);
  if (l11 != l00 && l11 != l10 && l11 != l01) access_line(l11);
}

// glm::mix(x, y, a) is x * (1 - a) + y * a (glm/detail/func_common.inl); written out so that
// it is inlined into every sampling path, which GCC does not do for glm's out of the
// per-sample code, and computes exactly that.
[[gnu::always_inline]] inline glm::vec4 ExecTexUnit::blend(const Footprint& f) {
  const auto mix = [](const glm::vec4& x, const glm::vec4& y, float a) {
    return x * (1.0f - a) + y * a;
  };
  SKINSIM_DCHECK_INDEX(f.x0, f.level->width);
  SKINSIM_DCHECK_INDEX(f.x1, f.level->width);
  SKINSIM_DCHECK_INDEX(f.y0, f.level->height);
  SKINSIM_DCHECK_INDEX(f.y1, f.level->height);
  const glm::vec4* row0 = f.level->texels + static_cast<size_t>(f.y0) * f.level->width;
  const glm::vec4* row1 = f.level->texels + static_cast<size_t>(f.y1) * f.level->width;
  return mix(mix(row0[f.x0], row0[f.x1], f.ax), mix(row1[f.x0], row1[f.x1], f.ax), f.ay);
}

inline glm::vec4 ExecTexUnit::bilinear(const Texture2D& tex, std::uint64_t base, int level,
                                       glm::vec2 uv, bool blend_texels) {
  const Footprint f = fetch_footprint(tex, base, level, uv);
  return blend_texels ? blend(f) : glm::vec4(0.0f);
}

inline void ExecTexUnit::count_sample(const Texture2D& tex, Filter filter, bool dependent,
                                      std::uint64_t n) {
  counters_->samples_by_filter[static_cast<int>(filter)] += n;
  if (dependent) counters_->samples_dependent += n;
  if (tex.texel_bytes() > 4) counters_->samples_wide_format += n;
}

inline float ExecTexUnit::sample_shadow(int binding, const Varying<3>& coord) {
  return shadow(texture(binding), binding * kBindingAddressStride, coord.value, false);
}

inline float ExecTexUnit::sample_shadow(int binding, const glm::vec3& coord) {
  return shadow(texture(binding), binding * kBindingAddressStride, coord, true);
}

inline float ExecTexUnit::shadow(const Texture2D& tex, std::uint64_t base, glm::vec3 coord,
                                 bool dependent) {
  const glm::vec2 uv(coord);
  if (tex.sampler().filter == Filter::kNearest) {
    count_sample(tex, Filter::kNearest, dependent);
    return coord.z <= nearest(tex, base, 0, uv).x ? 1.0f : 0.0f;
  }
  count_sample(tex, Filter::kBilinear, dependent);
  return percentage_closer(fetch_footprint(tex, base, 0, uv), coord.z);
}

inline float ExecTexUnit::percentage_closer(const Footprint& f, float depth) {
  const auto lit = [&](int x, int y) { return depth <= f.level->at(x, y).x ? 1.0f : 0.0f; };
  const float top = lit(f.x0, f.y0) + (lit(f.x1, f.y0) - lit(f.x0, f.y0)) * f.ax;
  const float bottom = lit(f.x0, f.y1) + (lit(f.x1, f.y1) - lit(f.x0, f.y1)) * f.ax;
  return top + (bottom - top) * f.ay;
}

inline void ExecTexUnit::sample_shadow_lanes(int binding, const std::array<glm::vec3, 4>& coord,
                                             bool dependent, int n, TextureLineLog* lines,
                                             float* out) {
  const Texture2D& tex = texture(binding);
  const std::uint64_t base = binding * kBindingAddressStride;
  // Nearest comparisons, and maps whose addresses leave 32 bits: one by one.
  if (tex.sampler().filter == Filter::kNearest || tex.size_bytes() > kBindingAddressStride) {
    for (int l = 0; l < n; ++l) {
      lines_ = &lines[l];
      out[l] = shadow(tex, base, coord[l], dependent);
    }
    return;
  }
  count_sample(tex, Filter::kBilinear, dependent, n);
  std::array<float, FootprintLanes::kMax> u{}, v{};
  for (int l = 0; l < n; ++l) {
    u[l] = coord[l].x;
    v[l] = coord[l].y;
  }
  const LevelView& level = tex.level(0);
  FootprintLanes f;
  address_footprints(u.data(), v.data(), n, level, tex.sampler().wrap,
                     static_cast<std::uint32_t>(base + tex.level_offset(0)),
                     static_cast<std::uint32_t>(tex.texel_bytes()), lines[0].line_shift(), f);
  for (int l = 0; l < n; ++l) {
    lines_ = &lines[l];
    record_footprint(f.lines[0][l], f.lines[1][l], f.lines[2][l], f.lines[3][l]);
    out[l] = percentage_closer({&level, f.x0[l], f.x1[l], f.y0[l], f.y1[l], f.ax[l], f.ay[l]},
                               coord[l].z);
  }
}

inline ExecTexUnit::LevelChoice ExecTexUnit::choose_levels(const Texture2D& tex,
                                                           const LodInput& lod) {
  const int max_level = tex.level_count() - 1;
  if (max_level == 0) return {};  // single-level textures skip the LOD entirely
  if (tex.sampler().filter != Filter::kTrilinear) {
    // round(lambda) clamped to the chain.
    const int level =
        lod.is_rho2
            ? filtering::nearest_level(lod.value, max_level)
            : static_cast<int>(std::clamp(lod.value, 0.0f, static_cast<float>(max_level)) + 0.5f);
    return {level, level, 0.0f};
  }
  // Magnification (rho^2 <= 1, lambda <= 0) clamps to level 0 whatever lambda is, so the
  // common close-up case needs no logarithm.
  const float lambda = !lod.is_rho2        ? lod.value
                       : lod.value <= 1.0f ? 0.0f
                                           : filtering::lod_from_rho2(lod.value);
  const float clamped = std::clamp(lambda, 0.0f, static_cast<float>(max_level));
  const int l0 = static_cast<int>(clamped);
  return {l0, std::min(l0 + 1, max_level), clamped - static_cast<float>(l0)};
}

// The TMU fetches both levels of a trilinear sample even when the blend weight is 0 (the cost
// model charges a trilinear sample as two bilinear ones), so both footprints go through the
// cache. The host skips blending the second when its weight is 0 and the result is exactly
// the first: RGBA8 texels are finite and >= +0, so a * 1 + b * 0 == a bit for bit.
inline bool second_level_unused(const Texture2D& tex, float weight) {
  return weight == 0.0f && tex.format() == TexelFormat::kRGBA8;
}

inline glm::vec4 ExecTexUnit::filtered(const Texture2D& tex, std::uint64_t base, glm::vec2 uv,
                                       const LodInput& lod, bool dependent) {
  const Filter filter = tex.sampler().filter;
  count_sample(tex, filter, dependent);
  const LevelChoice levels = choose_levels(tex, lod);
  if (filter != Filter::kTrilinear) {
    return filter == Filter::kNearest ? nearest(tex, base, levels.first, uv)
                                      : bilinear(tex, base, levels.first, uv, true);
  }
  const glm::vec4 a = bilinear(tex, base, levels.first, uv, true);
  const bool second_unused = second_level_unused(tex, levels.weight);
  const glm::vec4 b = bilinear(tex, base, levels.second, uv, !second_unused);
  return second_unused ? a : glm::mix(a, b, levels.weight);
}

inline void ExecTexUnit::filtered_lanes(const Texture2D& tex, std::uint64_t base,
                                        const std::array<glm::vec2, 4>& uv,
                                        const std::array<LodInput, 4>& lod, bool dependent, int n,
                                        TextureLineLog* lines, glm::vec4* out) {
  const Filter filter = tex.sampler().filter;
  // Nearest samples, and textures whose addresses leave 32 bits: one by one.
  if (filter == Filter::kNearest || tex.size_bytes() > kBindingAddressStride) {
    for (int l = 0; l < n; ++l) {
      lines_ = &lines[l];
      out[l] = filtered(tex, base, uv[l], lod[l], dependent);
    }
    return;
  }
  count_sample(tex, filter, dependent, n);
  // Lane l addresses fragment l's first level, lane 4 + l its second (a trilinear sample's);
  // the lanes of fragments past n repeat fragment 0's (f1 to f3: the fragments in lanes 1-3).
  std::array<LevelChoice, 4> choice{};
  for (int l = 0; l < n; ++l) choice[l] = choose_levels(tex, lod[l]);
  const int f1 = n > 1 ? 1 : 0, f2 = n > 2 ? 2 : 0, f3 = n > 3 ? 3 : 0;
  LevelSamples samples;
  samples.u[0] = samples.u[1] = Float4{uv[0].x, uv[f1].x, uv[f2].x, uv[f3].x};
  samples.v[0] = samples.v[1] = Float4{uv[0].y, uv[f1].y, uv[f2].y, uv[f3].y};
  for (int half = 0; half < 2; ++half) {
    const auto level = [&](int l) { return half == 0 ? choice[l].first : choice[l].second; };
    const LevelView *l0 = &tex.level(level(0)), *l1 = &tex.level(level(f1)),
                    *l2 = &tex.level(level(f2)), *l3 = &tex.level(level(f3));
    samples.width[half] = Int4{l0->width, l1->width, l2->width, l3->width};
    samples.height[half] = Int4{l0->height, l1->height, l2->height, l3->height};
    const auto at = [&](int l) {
      return static_cast<std::uint32_t>(base + tex.level_offset(level(l)));
    };
    samples.base[half] = Uint4{at(0), at(f1), at(f2), at(f3)};
  }
  FootprintLanes f;
  address_footprints(samples, tex.sampler().wrap, static_cast<std::uint32_t>(tex.texel_bytes()),
                     lines[0].line_shift(), f);
  const auto texels = [&](int lane, int level) {
    record_footprint(f.lines[0][lane], f.lines[1][lane], f.lines[2][lane], f.lines[3][lane]);
    return Footprint{&tex.level(level), f.x0[lane], f.x1[lane], f.y0[lane],
                     f.y1[lane],        f.ax[lane], f.ay[lane]};
  };
  for (int l = 0; l < n; ++l) {
    lines_ = &lines[l];
    const glm::vec4 first = blend(texels(l, choice[l].first));
    if (filter != Filter::kTrilinear) {
      out[l] = first;
      continue;
    }
    const Footprint second = texels(4 + l, choice[l].second);
    out[l] = second_level_unused(tex, choice[l].weight)
                 ? first
                 : glm::mix(first, blend(second), choice[l].weight);
  }
}

inline float ExecTexUnit::rho2_of(const Texture2D& tex, const Varying<2>& uv) {
  if (tex.level_count() == 1) return 0.0f;  // a single-level texture needs no footprint
  const float w = static_cast<float>(tex.width()), h = static_cast<float>(tex.height());
  return filtering::footprint_rho2(uv.ddx.x * w, uv.ddx.y * h, uv.ddy.x * w, uv.ddy.y * h);
}

inline void ExecTexUnit::sample_lanes(int binding, const std::array<Varying<2>, 4>& uv, int n,
                                      TextureLineLog* lines, glm::vec4* out) {
  const Texture2D& tex = texture(binding);
  std::array<glm::vec2, 4> at;
  std::array<LodInput, 4> lod;
  for (int l = 0; l < 4; ++l) {
    at[l] = uv[l].value;
    lod[l] = LodInput::from_rho2(rho2_of(tex, uv[l]));
  }
  filtered_lanes(tex, binding * kBindingAddressStride, at, lod, false, n, lines, out);
}

inline void ExecTexUnit::sample_lod_lanes(int binding, const std::array<glm::vec2, 4>& uv,
                                          const std::array<float, 4>& lod, int n,
                                          TextureLineLog* lines, glm::vec4* out) {
  std::array<LodInput, 4> lods;
  for (int l = 0; l < 4; ++l) lods[l] = LodInput::explicit_lod(lod[l]);
  filtered_lanes(texture(binding), binding * kBindingAddressStride, uv, lods, true, n, lines, out);
}

// Always inlined into the shader, so that the derivative arithmetic of the coordinates
// (ExecFragIn::texcoord) is only done where a mip chain needs it: the 9 taps of a blur over
// a single-level render target skip it (-2 to -3% of a default frame on 2 threads).
[[gnu::always_inline]] inline glm::vec4 ExecTexUnit::sample(int binding, const Varying<2>& uv) {
  const Texture2D& tex = texture(binding);
  return filtered(tex, binding * kBindingAddressStride, uv.value,
                  LodInput::from_rho2(rho2_of(tex, uv)), false);
}

template <int N, class Coord>
std::array<glm::vec4, N> ExecTexUnit::sample_each(int binding, const Coord& coord) {
  // Computed coordinates (a glm::vec2) make dependent reads, as sample(binding, vec2) does.
  constexpr bool kDependent = std::is_same_v<std::decay_t<decltype(coord(0))>, glm::vec2>;
  const auto uv_of = [&](int i) -> glm::vec2 {
    if constexpr (kDependent) {
      return coord(i);
    } else {
      return coord(i).value;
    }
  };
  std::array<glm::vec4, N> out;
  const Texture2D& tex = texture(binding);
  const std::uint64_t base = binding * kBindingAddressStride;
  // What sample() does for a single-level bilinear texture (level 0 whatever the level of
  // detail, bilinear), with the addresses in 32-bit lanes, which the binding's region bounds.
  if (tex.level_count() != 1 || tex.sampler().filter != Filter::kBilinear ||
      tex.size_bytes() > kBindingAddressStride) {
    for (int i = 0; i < N; ++i) out[i] = sample(binding, coord(i));
    return out;
  }
  const LevelView& level = tex.level(0);
  count_sample(tex, Filter::kBilinear, kDependent, N);
  for (int first = 0; first < N; first += FootprintLanes::kMax) {
    const int n = std::min(FootprintLanes::kMax, N - first);
    std::array<float, FootprintLanes::kMax> u{}, v{};  // lanes from n on: unused
    for (int i = 0; i < n; ++i) {
      const glm::vec2 uv = uv_of(first + i);
      u[i] = uv.x;
      v[i] = uv.y;
    }
    FootprintLanes f;
    address_footprints(u.data(), v.data(), n, level, tex.sampler().wrap,
                       static_cast<std::uint32_t>(base + tex.level_offset(0)),
                       static_cast<std::uint32_t>(tex.texel_bytes()), lines_->line_shift(), f);
    for (int i = 0; i < n; ++i) {
      record_footprint(f.lines[0][i], f.lines[1][i], f.lines[2][i], f.lines[3][i]);
      out[first + i] = blend({&level, f.x0[i], f.x1[i], f.y0[i], f.y1[i], f.ax[i], f.ay[i]});
    }
  }
  return out;
}

inline glm::vec4 ExecTexUnit::sample_lod(int binding, const glm::vec2& uv, float lod) {
  return filtered(texture(binding), binding * kBindingAddressStride, uv,
                  LodInput::explicit_lod(lod), true);
}

}  // namespace skinsim::sim

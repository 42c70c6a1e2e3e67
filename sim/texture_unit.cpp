#include "sim/texture_unit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace skinsim::sim {

namespace {

int wrap_coord(int i, int size, Wrap wrap) {
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
FloorSplit floor_split(float v) {
  constexpr float kLimit = 1073741824.0f;
  v = v > -kLimit ? (v < kLimit ? v : kLimit) : -kLimit;  // NaN fails both: -kLimit
  int i = static_cast<int>(v);  // truncates toward zero
  i -= v < static_cast<float>(i) ? 1 : 0;
  return {i, v - static_cast<float>(i)};
}

// Morton code of x + 1 from the Morton code of x (x in the even bits): filling the odd
// bits with ones makes the carry ripple across them.
std::uint64_t morton_increment(std::uint64_t spread) {
  constexpr std::uint64_t kEven = 0x5555555555555555ull;
  return ((spread | ~kEven) + 1) & kEven;
}

std::uint64_t spread_next(std::uint64_t spread_prev, int prev, int next) {
  return next == prev + 1 ? morton_increment(spread_prev) : morton_spread(static_cast<std::uint32_t>(next));
}

// Squared footprint length rho^2 in texels (OpenGL ES 2.0 spec 3.7.7: rho = max of the
// two screen-axis footprint lengths); lambda = log2(rho).
float footprint_rho2(float du_dx, float dv_dx, float du_dy, float dv_dy) {
  return std::max(du_dx * du_dx + dv_dx * dv_dx, du_dy * du_dy + dv_dy * dv_dy);
}

float lod_from_rho2(float rho2) { return rho2 > 0.0f ? 0.5f * std::log2(rho2) : -1000.0f; }

// The level a nearest-mip sample uses, round(lambda) clamped to the chain, found from the
// exponent of rho^2 alone: with rho^2 = m 2^e (m in [1,2)), round(e/2 + log2(m)/2) =
// floor((e+1)/2). Exact, and no logarithm on the common path.
int nearest_level(float rho2, int max_level) {
  if (max_level == 0 || !(rho2 >= 1.0f)) return 0;  // also catches NaN
  if (std::isinf(rho2)) return max_level;
  const int e = std::ilogb(rho2);
  return std::min((e + 1) / 2, max_level);
}

}  // namespace

const Texture2D& ExecTexUnit::texture(int binding) const {
  const Texture2D* t = bindings_ ? bindings_->textures[binding] : nullptr;
  if (!t) throw std::logic_error("shader sampled unbound 2D texture slot " + std::to_string(binding));
  return *t;
}

const TextureCube& ExecTexUnit::cube(int binding) const {
  const TextureCube* t = bindings_ ? bindings_->cubes[binding] : nullptr;
  if (!t) throw std::logic_error("shader sampled unbound cube slot " + std::to_string(binding));
  return *t;
}

glm::vec4 ExecTexUnit::nearest(const Texture2D& tex, std::uint64_t base, int level, glm::vec2 uv) {
  const MipLevel& l = tex.level(level);
  const int x = wrap_coord(floor_split(uv.x * static_cast<float>(l.width)).whole, l.width, tex.sampler().wrap);
  const int y = wrap_coord(floor_split(uv.y * static_cast<float>(l.height)).whole, l.height, tex.sampler().wrap);
  ++counters_->texels_touched;
  access_line(base + tex.texel_offset(level, x, y));
  return l.at(x, y);
}

glm::vec4 ExecTexUnit::bilinear(const Texture2D& tex, std::uint64_t base, int level,
                                glm::vec2 uv) {
  const MipLevel& l = tex.level(level);
  const Wrap wrap = tex.sampler().wrap;
  const FloorSplit fx = floor_split(uv.x * static_cast<float>(l.width) - 0.5f);
  const FloorSplit fy = floor_split(uv.y * static_cast<float>(l.height) - 0.5f);
  const float ax = fx.fraction, ay = fy.fraction;
  const int x0 = wrap_coord(fx.whole, l.width, wrap);
  const int x1 = wrap_coord(fx.whole + 1, l.width, wrap);
  const int y0 = wrap_coord(fy.whole, l.height, wrap);
  const int y1 = wrap_coord(fy.whole + 1, l.height, wrap);

  // The 2x2 footprint's texel addresses in the twiddled layout, and the distinct cache lines
  // among them, looked up in footprint order (usually one: a 64-byte line holds a 4x4
  // RGBA8 block).
  const std::uint64_t level_base = base + tex.level_offset(level);
  const std::uint64_t bpp = tex.texel_bytes();
  const std::uint64_t sx0 = morton_spread(static_cast<std::uint32_t>(x0));
  const std::uint64_t sy0 = morton_spread(static_cast<std::uint32_t>(y0)) << 1;
  const std::uint64_t sx1 = spread_next(sx0, x0, x1);
  const std::uint64_t sy1 = spread_next(sy0 >> 1, y0, y1) << 1;
  const std::uint64_t a00 = level_base + (sx0 | sy0) * bpp, a10 = level_base + (sx1 | sy0) * bpp;
  const std::uint64_t a01 = level_base + (sx0 | sy1) * bpp, a11 = level_base + (sx1 | sy1) * bpp;
  const std::uint64_t l00 = cache_->line_of(a00), l10 = cache_->line_of(a10);
  const std::uint64_t l01 = cache_->line_of(a01), l11 = cache_->line_of(a11);
  counters_->texels_touched += 4;
  access_line(a00);
  if (l10 != l00) access_line(a10);
  if (l01 != l00 && l01 != l10) access_line(a01);
  if (l11 != l00 && l11 != l10 && l11 != l01) access_line(a11);

  const glm::vec4* row0 = &l.texels[static_cast<size_t>(y0) * l.width];
  const glm::vec4* row1 = &l.texels[static_cast<size_t>(y1) * l.width];
  return glm::mix(glm::mix(row0[x0], row0[x1], ax), glm::mix(row1[x0], row1[x1], ax), ay);
}

glm::vec4 ExecTexUnit::filtered(const Texture2D& tex, std::uint64_t base, glm::vec2 uv,
                                const LodInput& lod, bool dependent) {
  const Filter filter = tex.sampler().filter;
  ++counters_->samples_by_filter[static_cast<int>(filter)];
  if (dependent) ++counters_->samples_dependent;
  if (tex.format() != TexelFormat::kRGBA8) ++counters_->samples_wide_format;

  const int max_level = tex.level_count() - 1;
  if (filter != Filter::kTrilinear) {
    // round(lambda) clamped to the chain; single-level textures skip the LOD entirely.
    int level = 0;
    if (max_level > 0) {
      level = lod.is_rho2 ? nearest_level(lod.value, max_level)
                          : static_cast<int>(std::clamp(lod.value, 0.0f, static_cast<float>(max_level)) + 0.5f);
    }
    return filter == Filter::kNearest ? nearest(tex, base, level, uv) : bilinear(tex, base, level, uv);
  }
  const float lambda = lod.is_rho2 ? lod_from_rho2(lod.value) : lod.value;
  const float clamped = std::clamp(lambda, 0.0f, static_cast<float>(max_level));
  const int l0 = static_cast<int>(clamped);
  const int l1 = std::min(l0 + 1, max_level);
  const float t = clamped - static_cast<float>(l0);
  // The TMU fetches both levels even when the blend weight is 0 (the cost model charges a
  // trilinear sample as two bilinear ones).
  const glm::vec4 a = bilinear(tex, base, l0, uv);
  const glm::vec4 b = bilinear(tex, base, l1, uv);
  return glm::mix(a, b, t);
}

glm::vec4 ExecTexUnit::sample(int binding, const Varying<2>& uv) {
  const Texture2D& tex = texture(binding);
  const float w = static_cast<float>(tex.width()), h = static_cast<float>(tex.height());
  const float rho2 = footprint_rho2(uv.ddx.x * w, uv.ddx.y * h, uv.ddy.x * w, uv.ddy.y * h);
  return filtered(tex, binding * kBindingAddressStride, uv.value, LodInput::from_rho2(rho2), false);
}

glm::vec4 ExecTexUnit::sample_lod(int binding, const glm::vec2& uv, float lod) {
  return filtered(texture(binding), binding * kBindingAddressStride, uv, LodInput::explicit_lod(lod), true);
}

glm::vec4 ExecTexUnit::sample_cube(int binding, const Varying<3>& direction) {
  const TextureCube& c = cube(binding);
  const CubeCoord cc = cube_coord(direction.value);
  // Footprint: the angular change of the direction across a pixel, in face texels (a face
  // spans 2 units at distance 1 from the centre).
  const float len = std::max(glm::length(direction.value), 1e-6f);
  const float scale = 0.5f * static_cast<float>(c.size()) / len;
  const float dx = glm::length(direction.ddx) * scale, dy = glm::length(direction.ddy) * scale;
  return filtered(c.face(cc.face), binding * kBindingAddressStride + c.face_offset(cc.face),
                  cc.uv, LodInput::from_rho2(footprint_rho2(dx, 0.0f, dy, 0.0f)), false);
}

glm::vec4 ExecTexUnit::sample_cube_lod(int binding, const glm::vec3& direction, float lod) {
  const TextureCube& c = cube(binding);
  const CubeCoord cc = cube_coord(direction);
  return filtered(c.face(cc.face), binding * kBindingAddressStride + c.face_offset(cc.face),
                  cc.uv, LodInput::explicit_lod(lod), true);
}

}  // namespace skinsim::sim

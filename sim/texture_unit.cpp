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

float lod_from_gradients(float du_dx, float dv_dx, float du_dy, float dv_dy) {
  // OpenGL ES 2.0 spec 3.7.7: rho = max of the two screen-axis footprint lengths.
  const float rho2 = std::max(du_dx * du_dx + dv_dx * dv_dx, du_dy * du_dy + dv_dy * dv_dy);
  return rho2 > 0.0f ? 0.5f * std::log2(rho2) : -1000.0f;
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

void ExecTexUnit::touch(std::uint64_t address) {
  ++counters_->texels_touched;
  access_line(address);
}

void ExecTexUnit::access_line(std::uint64_t address) {
  ++counters_->cache_line_accesses;
  if (!cache_->access(address)) {
    ++counters_->cache_misses;
    counters_->dram_bytes += cache_->line_bytes();
  }
}

glm::vec4 ExecTexUnit::bilinear(const Texture2D& tex, std::uint64_t base, int level,
                                glm::vec2 uv) {
  const MipLevel& l = tex.level(level);
  const Wrap wrap = tex.sampler().wrap;
  const float fx = uv.x * static_cast<float>(l.width) - 0.5f;
  const float fy = uv.y * static_cast<float>(l.height) - 0.5f;
  const float flx = std::floor(fx), fly = std::floor(fy);
  const float ax = fx - flx, ay = fy - fly;
  const int x0 = wrap_coord(static_cast<int>(flx), l.width, wrap);
  const int x1 = wrap_coord(static_cast<int>(flx) + 1, l.width, wrap);
  const int y0 = wrap_coord(static_cast<int>(fly), l.height, wrap);
  const int y1 = wrap_coord(static_cast<int>(fly) + 1, l.height, wrap);

  // The 2x2 footprint's texel addresses in the twiddled layout, and the distinct cache lines
  // among them (usually one: a 64-byte line holds a 4x4 RGBA8 block).
  const std::uint64_t level_base = base + tex.level_offset(level);
  const std::uint64_t bpp = tex.texel_bytes();
  const std::uint64_t sx0 = morton_spread(x0), sx1 = morton_spread(x1);
  const std::uint64_t sy0 = morton_spread(y0) << 1, sy1 = morton_spread(y1) << 1;
  const std::uint64_t addresses[4] = {level_base + (sx0 | sy0) * bpp, level_base + (sx1 | sy0) * bpp,
                                      level_base + (sx0 | sy1) * bpp, level_base + (sx1 | sy1) * bpp};
  counters_->texels_touched += 4;
  std::uint64_t seen[4];
  int seen_count = 0;
  for (const std::uint64_t address : addresses) {
    const std::uint64_t line = cache_->line_of(address);
    bool repeat = false;
    for (int i = 0; i < seen_count; ++i) repeat = repeat || seen[i] == line;
    if (repeat) continue;
    seen[seen_count++] = line;
    access_line(address);
  }

  const glm::vec4* row0 = &l.texels[static_cast<size_t>(y0) * l.width];
  const glm::vec4* row1 = &l.texels[static_cast<size_t>(y1) * l.width];
  const glm::vec4 top = glm::mix(row0[x0], row0[x1], ax);
  const glm::vec4 bottom = glm::mix(row1[x0], row1[x1], ax);
  return glm::mix(top, bottom, ay);
}

glm::vec4 ExecTexUnit::filtered(const Texture2D& tex, std::uint64_t base, glm::vec2 uv,
                                float lod, bool dependent) {
  const Filter filter = tex.sampler().filter;
  ++counters_->samples_by_filter[static_cast<int>(filter)];
  if (dependent) ++counters_->samples_dependent;
  if (tex.format() != TexelFormat::kRGBA8) ++counters_->samples_wide_format;

  const float max_level = static_cast<float>(tex.level_count() - 1);
  if (filter == Filter::kNearest) {
    const int level = static_cast<int>(std::clamp(std::round(lod), 0.0f, max_level));
    const MipLevel& l = tex.level(level);
    const int x = wrap_coord(static_cast<int>(std::floor(uv.x * l.width)), l.width, tex.sampler().wrap);
    const int y = wrap_coord(static_cast<int>(std::floor(uv.y * l.height)), l.height, tex.sampler().wrap);
    touch(base + tex.texel_offset(level, x, y));
    return l.at(x, y);
  }
  if (filter == Filter::kBilinear) {
    const int level = static_cast<int>(std::clamp(std::round(lod), 0.0f, max_level));
    return bilinear(tex, base, level, uv);
  }
  const float clamped = std::clamp(lod, 0.0f, max_level);
  const int l0 = static_cast<int>(std::floor(clamped));
  const int l1 = std::min(l0 + 1, tex.level_count() - 1);
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
  const float lod = lod_from_gradients(uv.ddx.x * w, uv.ddx.y * h, uv.ddy.x * w, uv.ddy.y * h);
  return filtered(tex, binding * kBindingAddressStride, uv.value, lod, false);
}

glm::vec4 ExecTexUnit::sample_lod(int binding, const glm::vec2& uv, float lod) {
  return filtered(texture(binding), binding * kBindingAddressStride, uv, lod, true);
}

glm::vec4 ExecTexUnit::sample_cube(int binding, const Varying<3>& direction) {
  const TextureCube& c = cube(binding);
  const CubeCoord cc = cube_coord(direction.value);
  // Footprint: the angular change of the direction across a pixel, in face texels (a face
  // spans 2 units at distance 1 from the centre).
  const float len = std::max(glm::length(direction.value), 1e-6f);
  const float scale = 0.5f * static_cast<float>(c.size()) / len;
  const float dx = glm::length(direction.ddx) * scale, dy = glm::length(direction.ddy) * scale;
  const float lod = lod_from_gradients(dx, 0.0f, dy, 0.0f);
  return filtered(c.face(cc.face), binding * kBindingAddressStride + c.face_offset(cc.face),
                  cc.uv, lod, false);
}

glm::vec4 ExecTexUnit::sample_cube_lod(int binding, const glm::vec3& direction, float lod) {
  const TextureCube& c = cube(binding);
  const CubeCoord cc = cube_coord(direction);
  return filtered(c.face(cc.face), binding * kBindingAddressStride + c.face_offset(cc.face),
                  cc.uv, lod, true);
}

}  // namespace skinsim::sim

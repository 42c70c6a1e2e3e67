#include "sim/texture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shading/fp16.h"
#include "util/text.h"
#include "util/unorm8.h"

namespace skinsim::sim {

int bytes_per_texel(TexelFormat format) {
  switch (format) {
    case TexelFormat::kRGBA8:
      return 4;
    case TexelFormat::kRGBA16F:
      return 8;
    case TexelFormat::kRGBA32F:
      return 16;
    case TexelFormat::kDepth16:
      return 2;
    case TexelFormat::kDepth24:
      return 4;
  }
  return 4;
}

bool is_depth_format(TexelFormat format) {
  return format == TexelFormat::kDepth16 || format == TexelFormat::kDepth24;
}

const char* format_name(TexelFormat format) {
  switch (format) {
    case TexelFormat::kRGBA8:
      return "rgba8";
    case TexelFormat::kRGBA16F:
      return "rgba16f";
    case TexelFormat::kRGBA32F:
      return "rgba32f";
    case TexelFormat::kDepth16:
      return "depth16";
    case TexelFormat::kDepth24:
      return "depth24";
  }
  return "?";
}

TexelFormat parse_format(const std::string& name) {
  const std::string lower = lowercase(name);
  if (lower == "rgba8") return TexelFormat::kRGBA8;
  if (lower == "rgba16f") return TexelFormat::kRGBA16F;
  if (lower == "rgba32f") return TexelFormat::kRGBA32F;
  throw std::invalid_argument("unknown texel format '" + name +
                              "' (expected rgba8, rgba16f or rgba32f)");
}

namespace {

float quantize_unorm8(float v) {
  return kUnorm8Value[unorm8_nearest(v)];
}

// Depth as a normalised integer of `steps` + 1 levels (NaN to 0, as UNORM conversion).
glm::vec4 quantize_depth(float v, float steps) {
  const float x = std::min(std::max(0.0f, v), 1.0f) * steps;
  return {std::floor(x + 0.5f) / steps, 0.0f, 0.0f, 0.0f};
}

std::uint64_t next_pow2(std::uint64_t v) {
  std::uint64_t p = 1;
  while (p < v) p <<= 1;
  return p;
}

MipLevel downsample(const MipLevel& src) {
  MipLevel dst;
  dst.width = std::max(1, src.width / 2);
  dst.height = std::max(1, src.height / 2);
  dst.texels.resize(static_cast<size_t>(dst.width) * dst.height);
  for (int y = 0; y < dst.height; ++y) {
    for (int x = 0; x < dst.width; ++x) {
      const int x0 = std::min(2 * x, src.width - 1), x1 = std::min(2 * x + 1, src.width - 1);
      const int y0 = std::min(2 * y, src.height - 1), y1 = std::min(2 * y + 1, src.height - 1);
      dst.texels[static_cast<size_t>(y) * dst.width + x] =
          0.25f * (src.at(x0, y0) + src.at(x1, y0) + src.at(x0, y1) + src.at(x1, y1));
    }
  }
  return dst;
}

}  // namespace

void quantize_span(const glm::vec4* values, glm::vec4* stored, std::size_t count,
                   TexelFormat format) {
  const auto each_channel = [&](auto round) {
    for (std::size_t i = 0; i < count; ++i) {
      const glm::vec4 v = values[i];
      stored[i] = {round(v.x), round(v.y), round(v.z), round(v.w)};
    }
  };
  switch (format) {
    case TexelFormat::kRGBA8:
      return each_channel(quantize_unorm8);
    case TexelFormat::kRGBA16F:
      return each_channel(round_to_fp16);
    case TexelFormat::kRGBA32F:
      std::copy(values, values + count, stored);
      return;
    case TexelFormat::kDepth16:
    case TexelFormat::kDepth24: {
      const float steps = format == TexelFormat::kDepth16 ? 65535.0f : 16777215.0f;
      for (std::size_t i = 0; i < count; ++i) stored[i] = quantize_depth(values[i].x, steps);
      return;
    }
  }
}

glm::vec4 quantize(const glm::vec4& value, TexelFormat format) {
  glm::vec4 stored;
  quantize_span(&value, &stored, 1, format);
  return stored;
}

Texture2D::Texture2D(std::string name, int width, int height, const std::vector<glm::vec4>& texels,
                     TexelFormat format, SamplerState sampler, bool mipmaps)
    : name_(std::move(name)), format_(format), sampler_(sampler) {
  if (width <= 0 || height <= 0 || texels.size() != static_cast<size_t>(width) * height) {
    throw std::invalid_argument("texture '" + name_ + "': bad size");
  }
  std::vector<MipLevel> levels;
  levels.push_back({width, height, texels});
  // Mips are filtered from the unquantised level above, then each level is quantised, as
  // an offline mip generator writing the format would do.
  while (mipmaps && (levels.back().width > 1 || levels.back().height > 1)) {
    levels.push_back(downsample(levels.back()));
  }
  if (!mipmaps && sampler_.filter == Filter::kTrilinear) sampler_.filter = Filter::kBilinear;
  adopt(std::move(levels));
}

Texture2D Texture2D::view_of_stored(std::string name, int width, int height,
                                    const glm::vec4* stored, TexelFormat format,
                                    SamplerState sampler) {
  if (width <= 0 || height <= 0 || stored == nullptr) {
    throw std::invalid_argument("texture '" + name + "': bad size");
  }
  Texture2D t;
  t.name_ = std::move(name);
  t.format_ = format;
  t.sampler_ = sampler;
  if (t.sampler_.filter == Filter::kTrilinear) t.sampler_.filter = Filter::kBilinear;
  t.levels_.push_back({width, height, stored});
  t.finish_layout();
  return t;
}

Texture2D::Texture2D(std::string name, std::vector<MipLevel> levels, TexelFormat format,
                     SamplerState sampler)
    : name_(std::move(name)), format_(format), sampler_(sampler) {
  if (levels.empty()) throw std::invalid_argument("texture '" + name_ + "': no levels");
  for (size_t i = 0; i < levels.size(); ++i) {
    const MipLevel& l = levels[i];
    if (l.width <= 0 || l.height <= 0 ||
        l.texels.size() != static_cast<size_t>(l.width) * l.height) {
      throw std::invalid_argument("texture '" + name_ + "': bad level " + std::to_string(i));
    }
    if (i > 0 && (l.width != std::max(1, levels[i - 1].width / 2) ||
                  l.height != std::max(1, levels[i - 1].height / 2))) {
      throw std::invalid_argument("texture '" + name_ + "': level " + std::to_string(i) +
                                  " is not half the size of the level above");
    }
  }
  if (levels.size() == 1 && sampler_.filter == Filter::kTrilinear) {
    sampler_.filter = Filter::kBilinear;
  }
  adopt(std::move(levels));
}

void Texture2D::adopt(std::vector<MipLevel> levels) {
  for (MipLevel& level : levels) {
    quantize_span(level.texels.data(), level.texels.data(), level.texels.size(), format_);
  }
  auto storage = std::make_shared<const std::vector<MipLevel>>(std::move(levels));
  levels_.clear();
  for (const MipLevel& l : *storage) levels_.push_back({l.width, l.height, l.texels.data()});
  storage_ = std::move(storage);
  finish_layout();
}

void Texture2D::finish_layout() {
  texel_bytes_ = bytes_per_texel(format_);
  level_offsets_.assign(1, 0);
  for (const LevelView& l : levels_) {
    // Each level occupies the power-of-two square its twiddled addresses span.
    const std::uint64_t side = next_pow2(static_cast<std::uint64_t>(std::max(l.width, l.height)));
    level_offsets_.push_back(level_offsets_.back() + side * side * bytes_per_texel(format_));
  }
}

TextureCube::TextureCube(std::string name, int size,
                         const std::array<std::vector<glm::vec4>, 6>& faces, TexelFormat format,
                         SamplerState sampler, bool mipmaps)
    : name_(std::move(name)) {
  sampler.wrap = Wrap::kClamp;
  for (int f = 0; f < 6; ++f) {
    faces_[f] = Texture2D(name_ + ".face" + std::to_string(f), size, size, faces[f], format,
                          sampler, mipmaps);
  }
  face_bytes_ = faces_[0].size_bytes();
}

CubeCoord cube_coord(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  int face;
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x >= 0 ? 0 : 1;
    ma = a.x;
    sc = d.x >= 0 ? -d.z : d.z;
    tc = -d.y;
  } else if (a.y >= a.z) {
    face = d.y >= 0 ? 2 : 3;
    ma = a.y;
    sc = d.x;
    tc = d.y >= 0 ? d.z : -d.z;
  } else {
    face = d.z >= 0 ? 4 : 5;
    ma = a.z;
    sc = d.z >= 0 ? d.x : -d.x;
    tc = -d.y;
  }
  if (ma <= 0.0f) return {4, {0.5f, 0.5f}};
  return {face, {0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)}};
}

}  // namespace skinsim::sim

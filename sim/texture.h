// Textures of the emulated GPU: 2D textures with mip chains and cube maps, in the texel
// formats the pipelines use. Texel values are kept as floats, already quantised to the
// format (RGBA8 to 1/255 steps, RGBA16F to half precision), so sampling sees exactly what
// the device would store. The texture-cache model addresses texels in PowerVR's twiddled
// (Morton) layout.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "sim/counters.h"
#include "util/check.h"

namespace skinsim::sim {

// kDepth16 / kDepth24: depth textures (OES_depth_texture, GL_UNSIGNED_SHORT / GL_UNSIGNED_INT
// on SGX5xx; the 24-bit one is stored in 32 bits), depth in the red channel.
enum class TexelFormat : std::uint8_t { kRGBA8, kRGBA16F, kRGBA32F, kDepth16, kDepth24 };
enum class Wrap : std::uint8_t { kClamp, kRepeat };

int bytes_per_texel(TexelFormat format);
const char* format_name(TexelFormat format);
bool is_depth_format(TexelFormat format);
// Parses a colour format "rgba8", "rgba16f", "rgba32f" (any case); throws
// std::invalid_argument otherwise.
TexelFormat parse_format(const std::string& name);
// Rounds a value to what the format stores (RGBA8: clamp to [0,1], nearest 1/255, NaN to 0;
// RGBA16F: IEEE half, round to nearest even; RGBA32F: unchanged; depth: red clamped to
// [0,1] and rounded to the nearest of 2^16 - 1 or 2^24 - 1 steps, the rest 0).
glm::vec4 quantize(const glm::vec4& value, TexelFormat format);
// quantize() over `count` values (`stored` may be `values`): one format dispatch per span.
void quantize_span(const glm::vec4* values, glm::vec4* stored, std::size_t count,
                   TexelFormat format);

// Morton order: the bits of x and y interleaved (x in the even bits), PowerVR's
// "twiddled" texture layout. Coordinates up to 16 bits.
namespace detail {
// The 8 bits of each byte value spread to the even bits of 16 (a table lookup is cheaper
// than the shift-and-mask sequence on the texture path, which spreads ~50M times a frame).
constexpr std::array<std::uint16_t, 256> make_morton_byte_table() {
  std::array<std::uint16_t, 256> table{};
  for (unsigned v = 0; v < 256; ++v) {
    unsigned spread = 0;
    for (unsigned bit = 0; bit < 8; ++bit) spread |= ((v >> bit) & 1u) << (2 * bit);
    table[v] = static_cast<std::uint16_t>(spread);
  }
  return table;
}
inline constexpr std::array<std::uint16_t, 256> kMortonByte = make_morton_byte_table();
}  // namespace detail

// Spreads the low 16 bits of x to the even bit positions.
inline std::uint64_t morton_spread(std::uint32_t x) {
  return detail::kMortonByte[x & 0xFFu] |
         (std::uint64_t{detail::kMortonByte[(x >> 8) & 0xFFu]} << 16);
}
inline std::uint64_t twiddle(std::uint32_t x, std::uint32_t y) {
  return morton_spread(x) | (morton_spread(y) << 1);
}

// One mip level's texels as built, row-major: what Texture2D's constructors take.
struct MipLevel {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> texels;
  const glm::vec4& at(int x, int y) const {
    SKINSIM_DCHECK_INDEX(x, width);
    SKINSIM_DCHECK_INDEX(y, height);
    return texels[static_cast<size_t>(y) * width + x];
  }
};

// One level as the sampler reads it: row-major texels that the texture owns or, for a view
// of a render target, the target owns.
struct LevelView {
  int width = 0;
  int height = 0;
  const glm::vec4* texels = nullptr;
  const glm::vec4& at(int x, int y) const {
    SKINSIM_DCHECK_INDEX(x, width);
    SKINSIM_DCHECK_INDEX(y, height);
    return texels[static_cast<size_t>(y) * width + x];
  }
};

struct SamplerState {
  Filter filter = Filter::kTrilinear;
  Wrap wrap = Wrap::kRepeat;
};

class Texture2D {
 public:
  Texture2D() = default;
  // Level 0 from `texels` (width*height, row-major), quantised to `format`; the mip chain
  // is box-filtered down to 1x1 when `mipmaps` is set.
  Texture2D(std::string name, int width, int height, const std::vector<glm::vec4>& texels,
            TexelFormat format, SamplerState sampler, bool mipmaps);
  // A single level over texels that are already stored values of `format` (a finished
  // render target), sampled in place as the GPU does: no copy, no mips, no second
  // quantisation. `stored` must outlive the texture and not change while it is sampled.
  static Texture2D view_of_stored(std::string name, int width, int height, const glm::vec4* stored,
                                  TexelFormat format, SamplerState sampler);
  // Explicit levels (e.g. a LUT whose levels hold different roughness); each level must be
  // half the size of the previous one (rounded down, at least 1).
  Texture2D(std::string name, std::vector<MipLevel> levels, TexelFormat format,
            SamplerState sampler);

  const std::string& name() const { return name_; }
  TexelFormat format() const { return format_; }
  const SamplerState& sampler() const { return sampler_; }
  int width() const { return levels_.front().width; }
  int height() const { return levels_.front().height; }
  int level_count() const { return static_cast<int>(levels_.size()); }
  const LevelView& level(int i) const {
    SKINSIM_DCHECK_INDEX(i, levels_.size());
    return levels_[i];
  }
  // Byte offset of a texel from the texture's base address (twiddled within each level).
  std::uint64_t texel_offset(int level, int x, int y) const {
    return level_offsets_[level] +
           twiddle(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) * texel_bytes_;
  }
  std::uint64_t level_offset(int level) const { return level_offsets_[level]; }
  std::uint64_t texel_bytes() const { return texel_bytes_; }
  std::uint64_t size_bytes() const { return level_offsets_.back(); }

 private:
  // Takes ownership of quantised levels and lays them out.
  void adopt(std::vector<MipLevel> levels);
  void finish_layout();

  std::string name_;
  TexelFormat format_ = TexelFormat::kRGBA8;
  SamplerState sampler_;
  // The texels, immutable once built, so copies of a texture share them; null for a view.
  std::shared_ptr<const std::vector<MipLevel>> storage_;
  std::vector<LevelView> levels_;
  std::vector<std::uint64_t> level_offsets_;  // level_count + 1 entries
  std::uint64_t texel_bytes_ = 4;
};

// Cube map: six faces (+X, -X, +Y, -Y, +Z, -Z, OpenGL convention), each a Texture2D with
// its own mip chain, laid out one after another in memory.
class TextureCube {
 public:
  TextureCube() = default;
  TextureCube(std::string name, int size, const std::array<std::vector<glm::vec4>, 6>& faces,
              TexelFormat format, SamplerState sampler, bool mipmaps);

  const std::string& name() const { return name_; }
  TexelFormat format() const { return faces_[0].format(); }
  const SamplerState& sampler() const { return faces_[0].sampler(); }
  int size() const { return faces_[0].width(); }
  const Texture2D& face(int i) const { return faces_[i]; }
  std::uint64_t face_offset(int i) const { return static_cast<std::uint64_t>(i) * face_bytes_; }

 private:
  std::string name_;
  std::array<Texture2D, 6> faces_;
  std::uint64_t face_bytes_ = 0;
};

// Maps a direction to (face, u, v) with u, v in [0,1] (OpenGL cube map convention).
struct CubeCoord {
  int face;
  glm::vec2 uv;
};
CubeCoord cube_coord(const glm::vec3& direction);

}  // namespace skinsim::sim

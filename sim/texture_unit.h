// The texture unit of one emulated core, as the Exec-mode shaders see it: filtered
// sampling of the bound textures, with every fetch counted and the distinct cache lines of
// every sample recorded for the core's texture cache (TextureLineLog, replayed in tile order).
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "sim/counters.h"
#include "sim/texture.h"
#include "sim/texture_line_log.h"

namespace skinsim::sim {

constexpr int kMaxTextureBindings = 8;

// A varying used directly as texture coordinates, with its screen-space derivatives (what
// the hardware's iterators provide for mip selection).
template <int N>
struct Varying {
  glm::vec<N, float> value{0.0f};
  glm::vec<N, float> ddx{0.0f};
  glm::vec<N, float> ddy{0.0f};
};

// Coordinates scaled by a constant (a tiling detail map), their derivatives with them, so the
// map is filtered at its own mip (pipeline/shaders/urp.h, sample_tiled).
template <int N>
Varying<N> scaled(const Varying<N>& v, float s) {
  return {v.value * s, v.ddx * s, v.ddy * s};
}

struct TextureBindings {
  std::array<const Texture2D*, kMaxTextureBindings> textures{};
  std::array<const TextureCube*, kMaxTextureBindings> cubes{};
};

class ExecTexUnit {
 public:
  ExecTexUnit(TextureLineLog* lines, TextureCounters* counters)
      : lines_(lines), counters_(counters) {}

  void bind(const TextureBindings* bindings) { bindings_ = bindings; }
  // Where the next samples count their work and record their cache lines (one tile's).
  void set_tile(TextureCounters* counters, TextureLineLog* lines) {
    counters_ = counters;
    lines_ = lines;
  }
  // Where the next samples record their cache lines (one fragment's of a batch: Exec4TexUnit).
  void set_lines(TextureLineLog* lines) { lines_ = lines; }
  TextureLineLog* lines() const { return lines_; }

  // Independent read: coordinates straight from a varying; LOD from its derivatives.
  glm::vec4 sample(int binding, const Varying<2>& uv);
  // Dependent reads: computed coordinates (LOD 0, or explicit).
  glm::vec4 sample(int binding, const glm::vec2& uv) { return sample_lod(binding, uv, 0.0f); }
  glm::vec4 sample_lod(int binding, const glm::vec2& uv, float lod);
  glm::vec4 sample_cube(int binding, const Varying<3>& direction);
  glm::vec4 sample_cube_lod(int binding, const glm::vec3& direction, float lod);
  // Depth-texture comparison (EXT_shadow_samplers' shadow2DEXT, compare func LEQUAL): 1
  // where coord.z <= the stored depth at coord.xy. A bilinear sampler compares the 2x2
  // footprint and filters the four results (the hardware PCF of iOS shadow samplers), a
  // nearest one compares one texel. Independent from a varying, dependent when computed.
  float sample_shadow(int binding, const Varying<3>& coord);
  float sample_shadow(int binding, const glm::vec3& coord);
  // Reads of one texture at N coordinates, coord(i) for i < N, in order: the values, counters
  // and cache-line records of N sample() calls with them (a Varying<2> an independent read, a
  // glm::vec2 a dependent one). A single-level bilinear texture's footprints are addressed up
  // to eight at a time (texture_footprints.h), which pays on a blur's taps.
  template <int N, class Coord>
  std::array<glm::vec4, N> sample_each(int binding, const Coord& coord);
  // Reads of one 2D texture by the first n (1 to 4) fragments of a batch (Exec4TexUnit),
  // fragment l's cache lines recorded in lines[l] (an array of four): what sample(binding, uv[l])
  // and sample_lod(binding, uv[l], lod[l]) give for each alone, the footprints addressed four at a
  // time (texture_footprints.h).
  void sample_lanes(int binding, const std::array<Varying<2>, 4>& uv, int n, TextureLineLog* lines,
                    glm::vec4* out);
  // sample_shadow(binding, coord[l]) for the first n (1 to 4) fragments of a batch, a
  // dependent read or not, each recording in lines[l].
  void sample_shadow_lanes(int binding, const std::array<glm::vec3, 4>& coord, bool dependent,
                           int n, TextureLineLog* lines, float* out);
  void sample_lod_lanes(int binding, const std::array<glm::vec2, 4>& uv,
                        const std::array<float, 4>& lod, int n, TextureLineLog* lines,
                        glm::vec4* out);

 private:
  // Level of detail as the sampler receives it: an explicit lambda, or the squared footprint
  // rho^2 from derivatives (lambda = log2(rho), taken only where a filter needs it).
  struct LodInput {
    float value;
    bool is_rho2;
    static LodInput from_rho2(float rho2) { return {rho2, true}; }
    static LodInput explicit_lod(float lambda) { return {lambda, false}; }
  };
  glm::vec4 filtered(const Texture2D& tex, std::uint64_t base, glm::vec2 uv, const LodInput& lod,
                     bool dependent);
  // filtered() for the first n of four fragments, each recording in its own lines[l].
  void filtered_lanes(const Texture2D& tex, std::uint64_t base, const std::array<glm::vec2, 4>& uv,
                      const std::array<LodInput, 4>& lod, bool dependent, int n,
                      TextureLineLog* lines, glm::vec4* out);
  // The squared footprint of a varying's derivatives on `tex` (0 for a single level).
  static float rho2_of(const Texture2D& tex, const Varying<2>& uv);
  // The levels filtered() blends for `lod`, and the weight of the second.
  struct LevelChoice {
    int first = 0, second = 0;
    float weight = 0.0f;
  };
  static LevelChoice choose_levels(const Texture2D& tex, const LodInput& lod);
  glm::vec4 nearest(const Texture2D& tex, std::uint64_t base, int level, glm::vec2 uv);
  float shadow(const Texture2D& tex, std::uint64_t base, glm::vec3 coord, bool dependent);
  // The PCF of a bilinear footprint: its four texels compared with `depth`, then filtered.
  struct Footprint;
  static float percentage_closer(const Footprint& f, float depth);
  // Counts n sample instructions of one kind.
  void count_sample(const Texture2D& tex, Filter filter, bool dependent, std::uint64_t n = 1);
  // A bilinear sample's 2x2 texels (x0/x1, y0/y1 after wrapping) and blend weights.
  struct Footprint {
    const LevelView* level;
    int x0, x1, y0, y1;
    float ax, ay;
  };
  // Counts the footprint's texels and records its distinct cache lines.
  Footprint fetch_footprint(const Texture2D& tex, std::uint64_t base, int level, glm::vec2 uv);
  // A footprint's texels counted and its distinct cache lines recorded in footprint order:
  // those of texels (x0,y0), (x1,y0), (x0,y1), (x1,y1).
  void record_footprint(std::uint64_t l00, std::uint64_t l10, std::uint64_t l01, std::uint64_t l11);
  // The bilinear blend of a footprint's four texels.
  static glm::vec4 blend(const Footprint& f);
  // `blend_texels` false: count and cache the footprint only (its value is not needed).
  glm::vec4 bilinear(const Texture2D& tex, std::uint64_t base, int level, glm::vec2 uv,
                     bool blend_texels);
  void access_line(std::uint64_t line);  // records one distinct cache line of a sample
  const Texture2D& texture(int binding) const;
  [[noreturn]] static void unbound(int binding, const char* kind);
  const TextureCube& cube(int binding) const;

  TextureLineLog* lines_;
  TextureCounters* counters_;
  const TextureBindings* bindings_ = nullptr;
};

// Each binding slot has its own region of the emulated address space, so texture
// addresses (and hence cache behaviour) do not depend on allocation order.
constexpr std::uint64_t kBindingAddressStride = std::uint64_t{1} << 28;
static_assert(kMaxTextureBindings * kBindingAddressStride <= std::uint64_t{1} << 32,
              "TextureLineLog keeps line numbers (addresses / line bytes) in 32 bits");

}  // namespace skinsim::sim

#include "sim/texture_unit_inline.h"  // IWYU pragma: export

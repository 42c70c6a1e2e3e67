#include "pipeline/reference/reference.h"

#include <emmintrin.h>
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <type_traits>

#include "pipeline/bake/brdf_lut.h"
#include "pipeline/bake/skin_profile.h"
#include "pipeline/bake/specular.h"
#include "pipeline/brdf_lut_texture.h"
#include "pipeline/frame_lights.h"
#include "pipeline/reference/dipole_diffusion.h"
#include "pipeline/reference/gbuffer_shaders.h"
#include "pipeline/shaders/background.h"
#include "pipeline/shaders/eye.h"
#include "sim/gpu.h"

namespace skinsim::pipeline {

namespace {

using scene::MaterialKind;

struct GBuffer {
  sim::RenderTarget position, normal, albedo, vertex_normal, nonskin;
};

template <class FS>
sim::PassCounters gbuffer_pass(
    const GpuScene& gs, const View& view, sim::RenderTarget& target, sim::Gpu& gpu,
    const std::function<typename FS::Uniforms(const GpuMaterial&)>& uniforms) {
  shaders::LightVertexUniforms thickness;  // the baked thickness, for VertexNormalFS
  thickness.shadow_coord = false;
  thickness.thickness = true;
  auto vs = sim::make_vertex_program<shaders::SurfaceVS>({view.view_proj, 0.0f, thickness});
  sim::RenderPassDesc pass;
  pass.name = target.name;
  pass.color = &target;
  for (const GpuMesh& m : gs.meshes()) {
    const GpuMaterial& mat = gs.materials()[m.material];
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.fragment_program = sim::make_fragment_program<FS>(uniforms(mat));
    d.textures.textures[0] = mat.base_color;
    d.textures.textures[1] = mat.normal;
    pass.draws.push_back(d);
  }
  return gpu.execute(pass);
}

float kind_code(MaterialKind k) {
  switch (k) {
    case MaterialKind::kSkin:
      return reference::kKindSkin;
    case MaterialKind::kEye:
      return reference::kKindEye;
    case MaterialKind::kOther:
      break;
  }
  return reference::kKindOther;
}

GBuffer render_gbuffer(const GpuScene& gs, const PipelineConfig& cfg, const View& view,
                       int threads) {
  const int w = cfg.width, h = cfg.height;
  sim::GpuConfig config;
  config.threads = threads;
  sim::Gpu gpu(config);
  GBuffer g{{"ref_position", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_normal", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_albedo", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_vertex_normal", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_nonskin", w, h, sim::TexelFormat::kRGBA32F}};
  gbuffer_pass<reference::PositionFS>(gs, view, g.position, gpu, [](const GpuMaterial& m) {
    return reference::PositionFS::Uniforms{kind_code(m.kind)};
  });
  gbuffer_pass<reference::ShadingNormalFS>(gs, view, g.normal, gpu, [](const GpuMaterial& m) {
    return reference::ShadingNormalFS::Uniforms{m.reflectivity, m.kind == MaterialKind::kSkin};
  });
  gbuffer_pass<reference::AlbedoFS>(gs, view, g.albedo, gpu, [](const GpuMaterial& m) {
    return reference::AlbedoFS::Uniforms{glm::vec3(m.base_color_factor)};
  });
  gbuffer_pass<reference::VertexNormalFS>(gs, view, g.vertex_normal, gpu, [](const GpuMaterial&) {
    return reference::VertexNormalFS::Uniforms{};
  });

  // Eyes and background: the same shaders as the pipelines (not what is studied), in float,
  // with the same shadow map.
  // A fixed, fine shadow map whatever the shadow knobs, so the reference does not depend on
  // them (knob.h: KnobSpec::reference).
  PipelineConfig light_cfg = cfg;
  light_cfg.shadows = true;
  light_cfg.shadow_map_size = 2048;
  light_cfg.shadow_depth = sim::TexelFormat::kDepth24;
  light_cfg.shadow_filter = ShadowFilter::kPcf2x2;
  light_cfg.shadow_taps = 4;
  light_cfg.shadow_tint.reset();
  std::vector<sim::PassCounters> light_passes;
  const FrameLights lights(gs, light_cfg, gpu, light_passes);
  auto vs = sim::make_vertex_program<shaders::SurfaceVS>(
      {view.view_proj, 0.0f, lights.vertex_uniforms(Transmission::kComputedElsewhere)});
  sim::RenderPassDesc pass;
  pass.name = "ref_nonskin";
  pass.color = &g.nonskin;
  pass.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  for (const GpuMesh& m : gs.meshes()) {
    const GpuMaterial& mat = gs.materials()[m.material];
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.textures.textures[0] = mat.base_color;
    lights.bind(d);
    const glm::vec3 factor(mat.base_color_factor);
    if (mat.kind == MaterialKind::kEye) {
      shaders::EyeFS::Uniforms u;
      u.eye = view.eye;
      u.lights = lights.uniforms();
      u.albedo_factor = factor;
      d.fragment_program = sim::make_fragment_program<shaders::EyeFS>(u);
      d.textures.cubes[shaders::EyeFS::kEnvironment] = &gs.environment();
    } else {
      d.fragment_program =
          sim::make_fragment_program<shaders::BackgroundFS>({lights.uniforms(), factor});
    }
    pass.draws.push_back(d);
  }
  gpu.execute(pass);
  return g;
}

float srgb_encode(float c) {
  c = std::max(c, 0.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Dual-lobe Kelemen/Szirmay-Kalos specular (d'Eon & Luebke, GPU Gems 3, ch. 14), exact.
float ks_specular(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v,
                  const bake::BrdfLutParams& p) {
  return p.weight1 * bake::ks_skin_specular(n, l, v, p.m1, p.rho_s, p.f0) +
         p.weight2 * bake::ks_skin_specular(n, l, v, p.m2, p.rho_s, p.f0);
}

// The hemisphere integrals behind the LUT's B and A channels depend on N.V only; a
// 1024-entry float table, linearly interpolated, stands in for per-pixel integration
// (its interpolation error is far below the 8-bit LUT's quantisation being measured).
class DirectionalTable {
 public:
  explicit DirectionalTable(const bake::BrdfLutParams& p) : entries_(kSize + 1) {
    tbb::parallel_for(0, kSize + 1, [&](int i) {
      const float n_dot_v = std::max(static_cast<float>(i) / kSize, 1e-4f);
      entries_[i] = bake::directional_reflectance(n_dot_v, p.m1, p.m2, p);
    });
  }
  // Fraction of light entering the skin (1 - specular albedo) and lobe-averaged Fresnel.
  void at(float n_dot_v, float& energy, float& fresnel) const {
    const float x = std::clamp(n_dot_v, 0.0f, 1.0f) * kSize;
    const int i = std::min(static_cast<int>(x), kSize - 1);
    const float t = x - static_cast<float>(i);
    const auto& a = entries_[i];
    const auto& b = entries_[i + 1];
    energy = 1.0f - static_cast<float>(a.albedo + (b.albedo - a.albedo) * t);
    fresnel = static_cast<float>(a.fresnel + (b.fresnel - a.fresnel) * t);
  }

 private:
  static constexpr int kSize = 1024;
  std::vector<bake::DirectionalReflectance> entries_;
};

glm::vec3 sample_cube(const sim::TextureCube& cube, const glm::vec3& direction) {
  const sim::CubeCoord c = sim::cube_coord(direction);
  const sim::LevelView& l = cube.face(c.face).level(0);
  const float fx = std::clamp(c.uv.x * l.width - 0.5f, 0.0f, l.width - 1.0f);
  const float fy = std::clamp(c.uv.y * l.height - 0.5f, 0.0f, l.height - 1.0f);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const int x1 = std::min(x0 + 1, l.width - 1), y1 = std::min(y0 + 1, l.height - 1);
  const float ax = fx - x0, ay = fy - y0;
  const glm::vec4 top = glm::mix(l.at(x0, y0), l.at(x1, y0), ax);
  const glm::vec4 bottom = glm::mix(l.at(x0, y1), l.at(x1, y1), ax);
  return glm::vec3(glm::mix(top, bottom, ay));
}

// exp(-x) for x >= 0 by linear interpolation in a table (relative error < 1e-5; beyond
// x = 32 the weight is below 1e-14 and taken as 0): the diffusion's kernel evaluations are
// most of the reference's time.
class ExpNegTable {
 public:
  ExpNegTable() : values_(kSize + 2) {
    for (int i = 0; i < kSize + 2; ++i) values_[i] = std::exp(-static_cast<float>(i) / kScale);
  }
  float at(float x) const {
    if (x >= kMax) return 0.0f;
    const float f = x * kScale;
    const int i = static_cast<int>(f);
    return values_[i] + (values_[i + 1] - values_[i]) * (f - static_cast<float>(i));
  }
  // at() in four lanes, each lane the same operations in the same order.
  __m128 at4(__m128 x) const {
    const __m128 f = _mm_mul_ps(x, _mm_set1_ps(kScale));
    // Lanes at or beyond kMax read the table's last entries and are then zeroed, as at().
    const __m128i index = _mm_cvttps_epi32(_mm_min_ps(f, _mm_set1_ps(kSize)));
    alignas(16) std::int32_t i[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(i), index);
    const __m128 a = _mm_setr_ps(values_[i[0]], values_[i[1]], values_[i[2]], values_[i[3]]);
    const __m128 b =
        _mm_setr_ps(values_[i[0] + 1], values_[i[1] + 1], values_[i[2] + 1], values_[i[3] + 1]);
    const __m128 g =
        _mm_add_ps(a, _mm_mul_ps(_mm_sub_ps(b, a), _mm_sub_ps(f, _mm_cvtepi32_ps(index))));
    return _mm_and_ps(_mm_cmplt_ps(x, _mm_set1_ps(kMax)), g);
  }

 private:
  static constexpr float kMax = 32.0f;
  static constexpr int kSize = 8192;
  static constexpr float kScale = kSize / kMax;
  std::vector<float> values_;
};

// Skin diffusion: M_i(p) = sum_q G_i(|x_p - x_q|) E(q) / sum_q G_i(|x_p - x_q|) over skin
// pixels q on a screen grid spanning +-3 sigma_i (projected at p's depth), for each of the
// profile's Gaussians; M = sum_i w_i M_i.
class Diffusion {
 public:
  Diffusion(const GBuffer& g, const std::vector<glm::vec3>& irradiance, const View& view,
            float units_per_mm)
      : width_(g.position.width),
        height_(g.position.height),
        samples_(g.position.pixels.size()),
        view_(view),
        units_per_mm_(units_per_mm) {
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const glm::vec4& q = g.position.pixels[i];
      samples_[i] = {glm::vec3(q), q.w, irradiance[i], 1.0f};
    }
  }

  glm::vec3 at(int x, int y) const {
    const glm::vec3 p = samples_[static_cast<std::size_t>(y) * width_ + x].position;
    const float px_per_unit = view_.pixels_per_unit(glm::length(p - view_.eye));
    const auto& gaussians = bake::skin_gaussians();
    constexpr std::size_t kCount = std::tuple_size_v<std::decay_t<decltype(gaussians)>>;
    std::array<Grid, kCount> grids;
    for (std::size_t k = 0; k < kCount; ++k) {
      const float variance = gaussians[k].variance_mm2 * units_per_mm_ * units_per_mm_;
      grids[k] = grid(x, y, variance, std::sqrt(variance) * px_per_unit);
    }
    // The four widest Gaussians together when all four use the full grid (the usual case at
    // display resolutions): one SIMD lane each.
    std::array<glm::vec3, kCount> diffused;
    constexpr std::size_t kWide = kCount - 4;
    const bool four_full =
        std::all_of(grids.begin() + kWide, grids.end(), [](const Grid& g) { return g.full; });
    for (std::size_t k = 0; k < (four_full ? kWide : kCount); ++k) {
      diffused[k] = convolve(x, y, p, grids[k]);
    }
    if (four_full) {
      const bool inside = std::all_of(grids.begin() + kWide, grids.end(), [](const Grid& g) {
        return g.i_begin == 0 && g.i_end == kMaxTaps && g.j_begin == 0 && g.j_end == kMaxTaps;
      });
      if (inside) {
        convolve_four<true>(x, y, p, &grids[kWide], &diffused[kWide]);
      } else {
        convolve_four<false>(x, y, p, &grids[kWide], &diffused[kWide]);
      }
    }
    glm::vec3 result(0.0f);
    for (std::size_t k = 0; k < kCount; ++k) result += gaussians[k].weight * diffused[k];
    return result;
  }

 private:
  // At most 13 x 13 taps per Gaussian: a grid step of sigma / 2 up to 3 sigma.
  static constexpr int kMaxTapsEachSide = 6;
  static constexpr int kMaxTaps = 2 * kMaxTapsEachSide + 1;

  // One Gaussian's screen grid around a pixel: its pixel offsets (the same along both axes)
  // and the runs of taps inside the image. lround is monotonic, so those runs are contiguous.
  struct Grid {
    float inv_two_variance = 0.0f;
    bool centre_only = false;  // narrower than half a pixel: the pixel's own irradiance
    bool full = false;         // all kMaxTaps offsets along each axis
    std::array<int, kMaxTaps> offset{};
    int i_begin = 0, i_end = 0, j_begin = 0, j_end = 0;
  };

  Grid grid(int x, int y, float variance, float sigma_px) const {
    Grid g;
    g.inv_two_variance = 1.0f / (2.0f * variance);
    if (sigma_px < 0.5f) {
      g.centre_only = true;
      return g;
    }
    const int n = std::min(kMaxTapsEachSide, static_cast<int>(std::ceil(3.0f * sigma_px)));
    g.full = n == kMaxTapsEachSide;
    const float step = 3.0f * sigma_px / static_cast<float>(n);
    for (int k = -n; k <= n; ++k) g.offset[k + n] = static_cast<int>(std::lround(k * step));
    const auto inside = [&](int centre, int size) {
      int begin = 0, end = 2 * n + 1;
      while (begin < end && centre + g.offset[begin] < 0) ++begin;
      while (end > begin && centre + g.offset[end - 1] >= size) --end;
      return std::pair{begin, end};
    };
    std::tie(g.i_begin, g.i_end) = inside(x, width_);
    std::tie(g.j_begin, g.j_end) = inside(y, height_);
    return g;
  }

  // One Gaussian's M_i(p): the skin taps' weights g = exp(-|x_q - x_p|^2 / 2 sigma^2) and the
  // sums of g E(q) and of g, taken tap by tap along each grid row (j outer, i inner). Four
  // taps' weights are computed at once (tap_weights); each tap then adds g * (r, g, b, 1) to
  // one register holding the three sums and the weight sum, so each lane is the sum of its
  // terms in tap order. A tap that is not skin weighs +0 and adds +0 (E is finite), which
  // leaves the non-negative sums as skipping it would.
  glm::vec3 convolve(int x, int y, const glm::vec3& p, const Grid& grid) const {
    const Sample& centre = samples_[static_cast<std::size_t>(y) * width_ + x];
    if (grid.centre_only) return centre.irradiance;
    const __m128 inv_two_variance = _mm_set1_ps(grid.inv_two_variance);
    __m128 sums = _mm_setzero_ps();  // r, g, b, weight
    for (int j = grid.j_begin; j < grid.j_end; ++j) {
      const Sample* row = &samples_[static_cast<std::size_t>(y + grid.offset[j]) * width_ + x];
      for (int i = grid.i_begin; i < grid.i_end; i += 4) {
        const int taps = std::min(4, grid.i_end - i);
        std::array<const Sample*, 4> tap{};
        for (int lane = 0; lane < 4; ++lane) {
          tap[lane] = lane < taps ? row + grid.offset[i + lane] : &centre;
        }
        alignas(16) std::array<float, 4> g;
        _mm_store_ps(g.data(), tap_weights(tap, p, inv_two_variance));
        for (int lane = 0; lane < taps; ++lane) {
          sums = _mm_add_ps(
              sums, _mm_mul_ps(_mm_set1_ps(g[lane]), _mm_load_ps(&tap[lane]->irradiance.x)));
        }
      }
    }
    alignas(16) std::array<float, 4> s;
    _mm_store_ps(s.data(), sums);
    return glm::vec3(s[0], s[1], s[2]) / s[3];  // the centre sample has weight 1
  }

  // convolve() of four full grids at once, one SSE lane each. Every lane does the scalar
  // path's operations in the same order (glm::dot is (x*x + y*y) + z*z; the weight's table
  // lookup is at4). A tap outside a lane's image runs, or on a sample that is not skin, adds
  // a weight of +0, which leaves the lane's non-negative sums exactly as skipping it would:
  // the four results equal convolve()'s to the last bit, at about half the time.
  // kInside: every tap of the four grids is inside the image (pixels at least three of the
  // widest sigmas from its borders, most of them), so no tap needs the lanes' runs checked.
  template <bool kInside>
  void convolve_four(int x, int y, const glm::vec3& p, const Grid* grids, glm::vec3* out) const {
    const Sample& centre = samples_[static_cast<std::size_t>(y) * width_ + x];
    const __m128 inv_two_variance =
        _mm_setr_ps(grids[0].inv_two_variance, grids[1].inv_two_variance, grids[2].inv_two_variance,
                    grids[3].inv_two_variance);
    __m128 sum_x = _mm_setzero_ps(), sum_y = _mm_setzero_ps(), sum_z = _mm_setzero_ps();
    __m128 weight_sum = _mm_setzero_ps();
    for (int j = 0; j < kMaxTaps; ++j) {
      std::array<const Sample*, 4> rows{};
      for (int lane = 0; lane < 4; ++lane) {
        const Grid& g = grids[lane];
        if (kInside || (j >= g.j_begin && j < g.j_end)) {
          rows[lane] = &samples_[static_cast<std::size_t>(y + g.offset[j]) * width_ + x];
        }
      }
      for (int i = 0; i < kMaxTaps; ++i) {
        std::array<const Sample*, 4> tap{};
        alignas(16) std::array<std::uint32_t, 4> inside{~0u, ~0u, ~0u, ~0u};
        for (int lane = 0; lane < 4; ++lane) {
          const Grid& g = grids[lane];
          if constexpr (kInside) {
            tap[lane] = rows[lane] + g.offset[i];
          } else {
            const bool in = rows[lane] != nullptr && i >= g.i_begin && i < g.i_end;
            tap[lane] = in ? rows[lane] + g.offset[i] : &centre;
            inside[lane] = in ? ~0u : 0u;
          }
        }
        __m128 e0 = _mm_load_ps(&tap[0]->irradiance.x), e1 = _mm_load_ps(&tap[1]->irradiance.x);
        __m128 e2 = _mm_load_ps(&tap[2]->irradiance.x), e3 = _mm_load_ps(&tap[3]->irradiance.x);
        _MM_TRANSPOSE4_PS(e0, e1, e2, e3);  // r, g, b, 1
        __m128 g = tap_weights(tap, p, inv_two_variance);
        if constexpr (!kInside) {
          g = _mm_and_ps(
              _mm_castsi128_ps(_mm_load_si128(reinterpret_cast<const __m128i*>(inside.data()))), g);
        }
        sum_x = _mm_add_ps(sum_x, _mm_mul_ps(g, e0));
        sum_y = _mm_add_ps(sum_y, _mm_mul_ps(g, e1));
        sum_z = _mm_add_ps(sum_z, _mm_mul_ps(g, e2));
        weight_sum = _mm_add_ps(weight_sum, g);
      }
    }
    alignas(16) std::array<float, 4> r, gr, b, w;
    _mm_store_ps(r.data(), sum_x);
    _mm_store_ps(gr.data(), sum_y);
    _mm_store_ps(b.data(), sum_z);
    _mm_store_ps(w.data(), weight_sum);
    for (int lane = 0; lane < 4; ++lane)
      out[lane] = glm::vec3(r[lane], gr[lane], b[lane]) / w[lane];
  }

  // What a tap reads, in one 32-byte record (position, the G-buffer's kind, irradiance), so
  // that a tap touches one cache line and four taps load as two 4x4 transposes.
  struct alignas(32) Sample {
    glm::vec3 position;
    float kind;
    glm::vec3 irradiance;
    float one;  // irradiance and one load as (r, g, b, 1): convolve() sums weights with light
  };

  // The weights of four taps, one lane each: exp(-|x_q - p|^2 inv_two_variance) by at4
  // (glm::dot's order, (x*x + y*y) + z*z), and +0 where the tap is not skin.
  __m128 tap_weights(const std::array<const Sample*, 4>& tap, const glm::vec3& p,
                     __m128 inv_two_variance) const {
    __m128 pos0 = _mm_load_ps(&tap[0]->position.x), pos1 = _mm_load_ps(&tap[1]->position.x);
    __m128 pos2 = _mm_load_ps(&tap[2]->position.x), pos3 = _mm_load_ps(&tap[3]->position.x);
    _MM_TRANSPOSE4_PS(pos0, pos1, pos2, pos3);  // x, y, z, kind of the four taps
    const __m128 dx = _mm_sub_ps(pos0, _mm_set1_ps(p.x)), dy = _mm_sub_ps(pos1, _mm_set1_ps(p.y));
    const __m128 dz = _mm_sub_ps(pos2, _mm_set1_ps(p.z));
    const __m128 dd =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    return _mm_and_ps(_mm_cmpeq_ps(pos3, _mm_set1_ps(reference::kKindSkin)),
                      exp_neg_.at4(_mm_mul_ps(dd, inv_two_variance)));
  }

  const ExpNegTable exp_neg_;
  int width_, height_;
  std::vector<Sample> samples_;
  const View& view_;
  float units_per_mm_;
};

// Fraction of a disc light of angular radius kLightRadiusRad around `l` visible from p:
// kShadowRays rays over the disc (a Fibonacci spiral, rotated per pixel by interleaved
// gradient noise, Jimenez 2014, so that the penumbra's steps become fine noise).
constexpr float kLightRadiusRad = 0.0175f;  // 1 degree: a softbox ~7 cm wide at 2 m
constexpr int kShadowRays = 16;
constexpr float kBackLightDistanceMm = 300.0f;

float visibility(const bake::RayScene& rays, const glm::vec3& p, const glm::vec3& l, int x, int y,
                 float offset, float reach) {
  const glm::vec3 helper = std::abs(l.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, l));
  const glm::vec3 b = glm::cross(l, t);
  const float noise = std::fmod(52.9829189f * std::fmod(0.06711056f * static_cast<float>(x) +
                                                            0.00583715f * static_cast<float>(y),
                                                        1.0f),
                                1.0f);
  const float rotation = 6.2831853f * noise;
  std::array<glm::vec3, kShadowRays> directions;
  for (int i = 0; i < kShadowRays; ++i) {
    const float r = kLightRadiusRad * std::sqrt((static_cast<float>(i) + 0.5f) / kShadowRays);
    const float phi = 2.39996323f * static_cast<float>(i) + rotation;
    directions[i] = glm::normalize(l + r * (std::cos(phi) * t + std::sin(phi) * b));
  }
  return static_cast<float>(rays.unoccluded(p, directions, offset, reach)) / kShadowRays;
}

// Transmittance of a slab `s` mm thick: the profile's Gaussians, as the pipelines use it
// (shaders/lights.h, Jimenez et al. 2010).
glm::vec3 transmittance(float s_mm) {
  glm::vec3 t(0.0f);
  for (const bake::GaussianTerm& g : bake::skin_gaussians()) {
    t += g.weight * std::exp(-s_mm * s_mm / g.variance_mm2);
  }
  return t;
}

}  // namespace

ReferenceFrame render_reference(const GpuScene& gs, const PipelineConfig& config, int threads) {
  const int w = config.width, h = config.height;
  const View view = make_view(gs, config);
  const GBuffer g = render_gbuffer(gs, config, view, threads);
  const scene::Scene& sc = gs.scene();
  const FrameLighting lighting = frame_lighting(gs, config);
  std::vector<scene::DirectionalLight> lights{lighting.key};
  if (lighting.has_back()) lights.push_back(lighting.back);
  // Shadow rays start this far off the surface (past the triangles they start on).
  const float ray_offset = 0.05f * sc.units_per_mm;
  // How far each light is: the key is distant; the back (rim) light stands 30 cm behind the
  // head, as in a studio, between it and any backdrop, which therefore casts no shadow of it.
  const std::vector<float> reach{std::numeric_limits<float>::infinity(),
                                 kBackLightDistanceMm * sc.units_per_mm};

  std::vector<glm::vec3> irradiance(static_cast<size_t>(w) * h, glm::vec3(0.0f));
  std::vector<float> visible(static_cast<size_t>(w) * h * lights.size(), 0.0f);  // per light
  const auto for_rows = [&](const std::function<void(int)>& row) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] { tbb::parallel_for(0, h, row); });
  };
  const auto for_blocks = [&](const std::function<void(int, int)>& pixel) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range2d<int>(0, h, 32, 0, w, 128),
                        [&](const tbb::blocked_range2d<int>& block) {
                          for (int y = block.rows().begin(); y < block.rows().end(); ++y) {
                            for (int x = block.cols().begin(); x < block.cols().end(); ++x) {
                              pixel(x, y);
                            }
                          }
                        });
    });
  };
  for_rows([&](int y) {
    for (int x = 0; x < w; ++x) {
      if (g.position.at(x, y).w != reference::kKindSkin) continue;
      const glm::vec3 n(g.normal.at(x, y));
      const glm::vec3 p(g.position.at(x, y));
      const glm::vec3 vertex_n(g.vertex_normal.at(x, y));
      // The light's physics, whatever the knobs: visibility is always ray cast and light
      // always crosses thin parts (the shadows and transmission knobs switch the
      // pipelines' approximations of these, measured against this).
      glm::vec3 e = lighting.ambient;
      for (std::size_t i = 0; i < lights.size(); ++i) {
        const scene::DirectionalLight& light = lights[i];
        const float n_dot_l = glm::dot(n, light.direction);
        if (n_dot_l <= 0.0f) continue;
        const float v = visibility(gs.rays(), p + vertex_n * ray_offset, light.direction, x, y,
                                   ray_offset, reach[i]);
        visible[(static_cast<size_t>(y) * w + x) * lights.size() + i] = v;
        e += light.radiance * n_dot_l * v;
      }
      {
        glm::vec3 back(0.0f);
        for (const scene::DirectionalLight& light : lights) {
          back +=
              light.radiance * std::clamp(0.3f - glm::dot(vertex_n, light.direction), 0.0f, 1.0f);
        }
        if (back != glm::vec3(0.0f)) {
          e += transmittance(g.vertex_normal.at(x, y).w) * back;
        }
      }
      irradiance[static_cast<size_t>(y) * w + x] = e;
    }
  });

  std::optional<Diffusion> gaussians;
  std::optional<DipoleDiffusion> dipole;
  if (config.reference_profile == ReferenceProfile::kDipole) {
    dipole.emplace(g.position, reference::kKindSkin, irradiance, view, sc.units_per_mm,
                   bake::dipole_terms(bake::jensen_skin1()));
  } else {
    gaussians.emplace(g, irradiance, view, sc.units_per_mm);
  }
  const auto diffused = [&](int x, int y) {
    return dipole ? dipole->at(x, y) : gaussians->at(x, y);
  };
  const bake::BrdfLutParams lut_params = brdf_lut_params(config);
  const DirectionalTable directional(lut_params);
  ReferenceFrame out{sim::RenderTarget("reference", w, h, sim::TexelFormat::kRGBA32F),
                     std::vector<std::uint8_t>(static_cast<size_t>(w) * h, 0)};
  // In blocks, not whole rows: a pixel's diffusion reads ~50 rows around it, and a block's
  // rows stay in the core's cache while a whole row's would not.
  for_blocks([&](int x, int y) {
    const glm::vec4 p = g.position.at(x, y);
    if (p.w != reference::kKindSkin) {
      out.frame.at(x, y) = g.nonskin.at(x, y);
      return;
    }
    out.skin_mask[static_cast<size_t>(y) * w + x] = 1;
    const glm::vec3 n(g.normal.at(x, y));
    const float reflectivity = g.normal.at(x, y).w;
    const glm::vec3 v = view.to_viewer(glm::vec3(p));
    const float n_dot_v = std::clamp(glm::dot(n, v), 0.0f, 1.0f);
    const glm::vec3 albedo(g.albedo.at(x, y));
    float energy = 0.0f, fresnel = 0.0f;
    directional.at(n_dot_v, energy, fresnel);
    const glm::vec3 diffuse = albedo * diffused(x, y) * energy;
    glm::vec3 specular(0.0f);
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const scene::DirectionalLight& light = lights[i];
      if (glm::dot(n, light.direction) <= 0.0f) continue;
      specular += light.radiance * ks_specular(n, light.direction, v, lut_params) * reflectivity *
                  visible[(static_cast<size_t>(y) * w + x) * lights.size() + i];
    }
    const glm::vec3 env =
        sample_cube(gs.environment_diffuse(), glm::vec3(g.vertex_normal.at(x, y)));
    const glm::vec3 color = diffuse + specular + env * fresnel * reflectivity;
    out.frame.at(x, y) =
        glm::vec4(srgb_encode(color.r), srgb_encode(color.g), srgb_encode(color.b), 1.0f);
  });
  return out;
}

}  // namespace skinsim::pipeline

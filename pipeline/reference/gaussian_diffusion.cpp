#include "pipeline/reference/gaussian_diffusion.h"

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "pipeline/bake/skin_profile.h"
#include "pipeline/reference/gaussian_diffusion.h"
#include "util/float_lanes.h"
#include "util/simd_dispatch.h"

namespace skinsim::pipeline {

// exp(-x) for x >= 0 by linear interpolation in a table (relative error < 1e-5; beyond
// x = 32 the weight is below 1e-14 and taken as 0): the diffusion's kernel evaluations are
// most of the reference's time. Not in the anonymous namespace: GaussianDiffusion::Impl, which
// has external linkage, holds one (GCC's -Wsubobject-linkage in a unity build).
class ExpNegTable {
 public:
  ExpNegTable() : values_(kSize + 2) {
    for (int i = 0; i < kSize + 2; ++i) values_[i] = std::exp(-static_cast<float>(i) / kScale);
  }
  // exp(-x) in four lanes: the table's entries either side of x * kScale, linearly
  // interpolated; 0 at and beyond kMax.
  __m128 at4(__m128 x) const {
    const __m128 f = _mm_mul_ps(x, _mm_set1_ps(kScale));
    // Lanes at or beyond kMax read the table's last entries and are then zeroed.
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

  // at4() in eight lanes (AVX), each lane the same operations in the same order.
  [[gnu::target("avx")]] __m256 at8(__m256 x) const {
    const __m256 f = _mm256_mul_ps(x, _mm256_set1_ps(kScale));
    const __m256i index = _mm256_cvttps_epi32(_mm256_min_ps(f, _mm256_set1_ps(kSize)));
    alignas(32) std::array<std::int32_t, 8> i;
    _mm256_store_si256(reinterpret_cast<__m256i*>(i.data()), index);
    const __m256 a = _mm256_setr_ps(values_[i[0]], values_[i[1]], values_[i[2]], values_[i[3]],
                                    values_[i[4]], values_[i[5]], values_[i[6]], values_[i[7]]);
    const __m256 b =
        _mm256_setr_ps(values_[i[0] + 1], values_[i[1] + 1], values_[i[2] + 1], values_[i[3] + 1],
                       values_[i[4] + 1], values_[i[5] + 1], values_[i[6] + 1], values_[i[7] + 1]);
    const __m256 g = _mm256_add_ps(
        a, _mm256_mul_ps(_mm256_sub_ps(b, a), _mm256_sub_ps(f, _mm256_cvtepi32_ps(index))));
    return _mm256_and_ps(_mm256_cmp_ps(x, _mm256_set1_ps(kMax), _CMP_LT_OS), g);
  }

 private:
  static constexpr float kMax = 32.0f;
  static constexpr int kSize = 8192;
  static constexpr float kScale = kSize / kMax;
  std::vector<float> values_;
};

namespace {

// Four floats from each of a and b in one AVX register: a's in the low half, b's in the high.
[[gnu::target("avx")]] inline __m256 load_pair(const float* a, const float* b) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(a)), _mm_load_ps(b), 1);
}

// _MM_TRANSPOSE4_PS in each 128-bit half: rows (x, y, z, w) of four records become x, y, z, w
// of the four.
[[gnu::target("avx")]] inline void transpose_halves(__m256& r0, __m256& r1, __m256& r2,
                                                    __m256& r3) {
  const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);
  const __m256 t2 = _mm256_unpacklo_ps(r2, r3), t3 = _mm256_unpackhi_ps(r2, r3);
  r0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
  r1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
  r2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
  r3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
}

}  // namespace

class GaussianDiffusion::Impl {
 public:
  Impl(const sim::RenderTarget& position, float kind_skin, const std::vector<glm::vec3>& irradiance,
       const View& view, float units_per_mm)
      : width_(position.width),
        height_(position.height),
        samples_(position.pixels.size()),
        kind_skin_(kind_skin),
        view_(view),
        units_per_mm_(units_per_mm) {
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const glm::vec4& q = position.pixels[i];
      samples_[i] = {glm::vec3(q), q.w, irradiance[i], 1.0f};
    }
  }

  // With AVX, consecutive skin pixels are diffused two at a time (diffuse_pair), one per
  // half of the AVX registers; otherwise, and for a last pixel without a partner, one at a
  // time (diffuse_alone). Both give each pixel the same bits.
  void row(int y, int x_begin, int x_end, glm::vec3* out) const {
    const bool avx = use_avx();
    std::optional<Pixel> waiting;  // a pixel waiting for its partner
    const auto finish = [&](const Pixel& px) { out[px.x - x_begin] = px.result(); };
    for (int x = x_begin; x < x_end; ++x) {
      if (sample(x, y).kind != kind_skin_) continue;
      Pixel px = prepare(x, y);
      if (!avx) {
        diffuse_alone(px);
        finish(px);
      } else if (!waiting) {
        waiting = std::move(px);
      } else {
        diffuse_pair(*waiting, px);
        finish(*waiting);
        finish(px);
        waiting.reset();
      }
    }
    if (waiting) {
      diffuse_alone(*waiting);
      finish(*waiting);
    }
  }

 private:
  static constexpr std::size_t kCount =
      std::tuple_size_v<std::remove_cvref_t<decltype(bake::skin_gaussians())>>;
  static constexpr std::size_t kWide = kCount - 4;  // the first of the four widest

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
    const Sample& centre = sample(x, y);
    if (grid.centre_only) return centre.irradiance;
    const __m128 inv_two_variance = _mm_set1_ps(grid.inv_two_variance);
    __m128 sums = _mm_setzero_ps();  // r, g, b, weight
    for (int j = grid.j_begin; j < grid.j_end; ++j) {
      const Sample* row = &sample(x, y + grid.offset[j]);
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

  // Four or eight lanes' sums of g * E (r, g, b) and of g, one Gaussian of one pixel per
  // lane: the four-lane kernel's (convolve_four) and the eight-lane one's (convolve_eight)
  // share them, so that both add and divide in the same order. Always inlined, so that in the
  // AVX kernel they are AVX code too (see quality/separable_stream.cpp).
  template <class Reg>
  struct Sums {
    static constexpr int kLanes = static_cast<int>(sizeof(Reg) / sizeof(float));
    Reg x{}, y{}, z{}, weight{};

    // One tap of every lane: weights g, light (r, g, b).
    [[gnu::always_inline]] void add(const Reg& g, const Reg& r, const Reg& gr, const Reg& b) {
      x += g * r;
      y += g * gr;
      z += g * b;
      weight += g;
    }
    // Each lane's M_i: the first four lanes to low[0..3], lanes 4-7 (eight lanes: a second
    // pixel's) to high[0..3].
    [[gnu::always_inline]] void normalise(glm::vec3* low, glm::vec3* high = nullptr) const {
      for (int lane = 0; lane < kLanes; ++lane) {
        glm::vec3& out = lane < 4 ? low[lane] : high[lane - 4];
        out = glm::vec3(x[lane], y[lane], z[lane]) / weight[lane];
      }
    }
  };

  // convolve() of four full grids at once, one SSE lane each. Every lane does the scalar
  // path's operations in the same order (glm::dot is (x*x + y*y) + z*z; the weight's table
  // lookup is at4). A tap outside a lane's image runs, or on a sample that is not skin, adds
  // a weight of +0, which leaves the lane's non-negative sums exactly as skipping it would:
  // the four results equal convolve()'s to the last bit, at about half the time.
  // kInside: every tap of the four grids is inside the image (pixels at least three of the
  // widest sigmas from its borders, most of them), so no tap needs the lanes' runs checked.
  template <bool kInside>
  void convolve_four(int x, int y, const glm::vec3& p, const Grid* grids, glm::vec3* out) const {
    const Sample& centre = sample(x, y);
    const __m128 inv_two_variance =
        _mm_setr_ps(grids[0].inv_two_variance, grids[1].inv_two_variance, grids[2].inv_two_variance,
                    grids[3].inv_two_variance);
    Sums<Float4> sums;
    for (int j = 0; j < kMaxTaps; ++j) {
      std::array<const Sample*, 4> rows{};
      for (int lane = 0; lane < 4; ++lane) {
        const Grid& g = grids[lane];
        if (kInside || (j >= g.j_begin && j < g.j_end)) {
          rows[lane] = &sample(x, y + g.offset[j]);
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
        sums.add(g, e0, e1, e2);
      }
    }
    sums.normalise(out);
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
    return _mm_and_ps(_mm_cmpeq_ps(pos3, _mm_set1_ps(kind_skin_)),
                      exp_neg_.at4(_mm_mul_ps(dd, inv_two_variance)));
  }

  // How a pixel's four widest Gaussians are convolved: one at a time when any of their grids
  // is not full (convolve), together in four lanes otherwise, with a check of each tap's
  // place in the image where a grid reaches beyond it.
  enum class Wide { kOneAtATime, kEdge, kInside };

  struct Pixel {
    int x = 0, y = 0;
    glm::vec3 p{0.0f};
    Wide wide = Wide::kOneAtATime;
    std::array<Grid, kCount> grids;
    std::array<glm::vec3, kCount> diffused;
    glm::vec3 result() const {
      const auto& gaussians = bake::skin_gaussians();
      glm::vec3 m(0.0f);
      for (std::size_t k = 0; k < kCount; ++k) m += gaussians[k].weight * diffused[k];
      return m;
    }
  };

  const Sample& sample(int x, int y) const {
    return samples_[static_cast<std::size_t>(y) * width_ + x];
  }

  // A pixel's grids, and how its four widest Gaussians are convolved.
  Pixel prepare(int x, int y) const {
    Pixel px;
    px.x = x;
    px.y = y;
    px.p = sample(x, y).position;
    const float px_per_unit = view_.pixels_per_unit(glm::length(px.p - view_.eye));
    const auto& gaussians = bake::skin_gaussians();
    for (std::size_t k = 0; k < kCount; ++k) {
      const float variance = gaussians[k].variance_mm2 * units_per_mm_ * units_per_mm_;
      px.grids[k] = grid(x, y, variance, std::sqrt(variance) * px_per_unit);
    }
    const auto wide = std::span(px.grids).subspan(kWide);
    if (std::all_of(wide.begin(), wide.end(), [](const Grid& g) { return g.full; })) {
      const bool inside = std::all_of(wide.begin(), wide.end(), [](const Grid& g) {
        return g.i_begin == 0 && g.i_end == kMaxTaps && g.j_begin == 0 && g.j_end == kMaxTaps;
      });
      px.wide = inside ? Wide::kInside : Wide::kEdge;
    }
    return px;
  }

  // How many of a pixel's Gaussians, from the narrowest, are convolved one at a time.
  static std::size_t one_at_a_time(const Pixel& px) {
    return px.wide == Wide::kOneAtATime ? kCount : kWide;
  }

  // The four widest Gaussians of a pixel that has them in four lanes.
  void convolve_wide(Pixel& px) const {
    if (px.wide == Wide::kInside) {
      convolve_four<true>(px.x, px.y, px.p, &px.grids[kWide], &px.diffused[kWide]);
    } else if (px.wide == Wide::kEdge) {
      convolve_four<false>(px.x, px.y, px.p, &px.grids[kWide], &px.diffused[kWide]);
    }
  }

  void diffuse_alone(Pixel& px) const {
    for (std::size_t k = 0; k < one_at_a_time(px); ++k) {
      px.diffused[k] = convolve(px.x, px.y, px.p, px.grids[k]);
    }
    convolve_wide(px);
  }

  // Two pixels in the halves of the AVX registers wherever their work has the same shape: a
  // Gaussian whose grids have the same runs of taps (convolve_two), and the four widest when
  // both have them inside the image (convolve_eight). The rest one pixel at a time.
  void diffuse_pair(Pixel& a, Pixel& b) const {
    for (std::size_t k = 0; k < std::max(one_at_a_time(a), one_at_a_time(b)); ++k) {
      const Grid& ga = a.grids[k];
      const Grid& gb = b.grids[k];
      const bool a_alone = k < one_at_a_time(a), b_alone = k < one_at_a_time(b);
      if (a_alone && b_alone && !ga.centre_only && !gb.centre_only && ga.i_begin == gb.i_begin &&
          ga.i_end == gb.i_end && ga.j_begin == gb.j_begin && ga.j_end == gb.j_end) {
        convolve_two(a, b, k);
        continue;
      }
      if (a_alone) a.diffused[k] = convolve(a.x, a.y, a.p, ga);
      if (b_alone) b.diffused[k] = convolve(b.x, b.y, b.p, gb);
    }
    if (a.wide == Wide::kInside && b.wide == Wide::kInside) {
      convolve_eight(a, b);
    } else {
      convolve_wide(a);
      convolve_wide(b);
    }
  }

  // Eight lanes of which the low four hold `low` and the high four `high`.
  [[gnu::target("avx")]] static __m256 halves(float low, float high) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_set1_ps(low)), _mm_set1_ps(high), 1);
  }

  // Each lane's centre pixel position.
  struct Centres {
    __m256 x, y, z;
  };

  // tap_weights of eight taps, one lane each, around `centre` (x, y, z per lane) with each
  // lane's 1 / 2 sigma^2: the four-lane operations in their order, with at8 for at4.
  [[gnu::target("avx")]] __m256 tap_weights8(const std::array<const Sample*, 8>& tap,
                                             const Centres& centre, __m256 inv_two_variance) const {
    __m256 x = load_pair(&tap[0]->position.x, &tap[4]->position.x);
    __m256 y = load_pair(&tap[1]->position.x, &tap[5]->position.x);
    __m256 z = load_pair(&tap[2]->position.x, &tap[6]->position.x);
    __m256 kind = load_pair(&tap[3]->position.x, &tap[7]->position.x);
    transpose_halves(x, y, z, kind);
    const __m256 dx = _mm256_sub_ps(x, centre.x), dy = _mm256_sub_ps(y, centre.y);
    const __m256 dz = _mm256_sub_ps(z, centre.z);
    const __m256 dd = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)),
                                    _mm256_mul_ps(dz, dz));
    return _mm256_and_ps(_mm256_cmp_ps(kind, _mm256_set1_ps(kind_skin_), _CMP_EQ_OQ),
                         exp_neg_.at8(_mm256_mul_ps(dd, inv_two_variance)));
  }

  // convolve() of Gaussian k for two pixels whose grids have the same runs of taps: a's sums
  // (r, g, b, weight) in the low half of one register, b's in the high half, each tap's
  // g * (r, g, b, 1) added in convolve()'s order, so each pixel gets convolve()'s bits.
  [[gnu::target("avx")]] void convolve_two(Pixel& a, Pixel& b, std::size_t k) const {
    const Grid& ga = a.grids[k];
    const Grid& gb = b.grids[k];
    const Sample& centre_a = sample(a.x, a.y);
    const Sample& centre_b = sample(b.x, b.y);
    const Centres centre = {halves(a.p.x, b.p.x), halves(a.p.y, b.p.y), halves(a.p.z, b.p.z)};
    const __m256 inv_two_variance = halves(ga.inv_two_variance, gb.inv_two_variance);
    __m256 sums = _mm256_setzero_ps();
    for (int j = ga.j_begin; j < ga.j_end; ++j) {
      const Sample* row_a = &sample(a.x, a.y + ga.offset[j]);
      const Sample* row_b = &sample(b.x, b.y + gb.offset[j]);
      for (int i = ga.i_begin; i < ga.i_end; i += 4) {
        const int taps = std::min(4, ga.i_end - i);
        std::array<const Sample*, 8> tap{};
        for (int lane = 0; lane < 4; ++lane) {
          tap[lane] = lane < taps ? row_a + ga.offset[i + lane] : &centre_a;
          tap[lane + 4] = lane < taps ? row_b + gb.offset[i + lane] : &centre_b;
        }
        alignas(32) std::array<float, 8> g;
        _mm256_store_ps(g.data(), tap_weights8(tap, centre, inv_two_variance));
        for (int lane = 0; lane < taps; ++lane) {
          sums = _mm256_add_ps(sums, _mm256_mul_ps(halves(g[lane], g[lane + 4]),
                                                   load_pair(&tap[lane]->irradiance.x,
                                                             &tap[lane + 4]->irradiance.x)));
        }
      }
    }
    alignas(32) std::array<float, 8> s;
    _mm256_store_ps(s.data(), sums);
    a.diffused[k] = glm::vec3(s[0], s[1], s[2]) / s[3];
    b.diffused[k] = glm::vec3(s[4], s[5], s[6]) / s[7];
  }

  // convolve_four<true> of two pixels at once in eight AVX lanes (a's four widest Gaussians
  // in the low half, b's in the high): each lane does the four-lane kernel's operations in
  // its order, so both pixels get its bits.
  [[gnu::target("avx")]] void convolve_eight(Pixel& a, Pixel& b) const {
    const Grid* grid_a = &a.grids[kWide];
    const Grid* grid_b = &b.grids[kWide];
    const Centres centre = {halves(a.p.x, b.p.x), halves(a.p.y, b.p.y), halves(a.p.z, b.p.z)};
    const __m256 inv_two_variance = _mm256_setr_ps(
        grid_a[0].inv_two_variance, grid_a[1].inv_two_variance, grid_a[2].inv_two_variance,
        grid_a[3].inv_two_variance, grid_b[0].inv_two_variance, grid_b[1].inv_two_variance,
        grid_b[2].inv_two_variance, grid_b[3].inv_two_variance);
    Sums<Float8> sums;
    for (int j = 0; j < kMaxTaps; ++j) {
      std::array<const Sample*, 8> rows;
      for (int l = 0; l < 4; ++l) {
        rows[l] = &sample(a.x, a.y + grid_a[l].offset[j]);
        rows[l + 4] = &sample(b.x, b.y + grid_b[l].offset[j]);
      }
      for (int i = 0; i < kMaxTaps; ++i) {
        std::array<const Sample*, 8> tap;
        for (int l = 0; l < 4; ++l) {
          tap[l] = rows[l] + grid_a[l].offset[i];
          tap[l + 4] = rows[l + 4] + grid_b[l].offset[i];
        }
        const __m256 g = tap_weights8(tap, centre, inv_two_variance);
        __m256 r = load_pair(&tap[0]->irradiance.x, &tap[4]->irradiance.x);
        __m256 gr = load_pair(&tap[1]->irradiance.x, &tap[5]->irradiance.x);
        __m256 bl = load_pair(&tap[2]->irradiance.x, &tap[6]->irradiance.x);
        __m256 one = load_pair(&tap[3]->irradiance.x, &tap[7]->irradiance.x);
        transpose_halves(r, gr, bl, one);  // r, g, b, 1
        sums.add(g, r, gr, bl);
      }
    }
    sums.normalise(&a.diffused[kWide], &b.diffused[kWide]);
  }

  const ExpNegTable exp_neg_;
  int width_, height_;
  std::vector<Sample> samples_;
  float kind_skin_;
  const View& view_;
  float units_per_mm_;
};

GaussianDiffusion::GaussianDiffusion(const sim::RenderTarget& position, float kind_skin,
                                     const std::vector<glm::vec3>& irradiance, const View& view,
                                     float units_per_mm)
    : impl_(std::make_unique<const Impl>(position, kind_skin, irradiance, view, units_per_mm)) {}

GaussianDiffusion::~GaussianDiffusion() = default;

void GaussianDiffusion::row(int y, int x_begin, int x_end, glm::vec3* out) const {
  impl_->row(y, x_begin, x_end, out);
}

}  // namespace skinsim::pipeline

#include "quality/error_map.h"

#include <array>

#include "quality/error.h"
#include "util/parallel_pixels.h"
#include "util/simd_dispatch.h"

namespace skinsim::quality {
namespace {

// Degree-6 polynomial fits of matplotlib's magma and viridis (Matt Zucker, CC0,
// shadertoy.com/view/WlfXRN); coefficients c0..c6 of t^0..t^6, per channel.
using Polynomial = std::array<glm::dvec3, 7>;

constexpr Polynomial kMagma{{
    {-0.002136485053939582, -0.000749655052795221, -0.005386127855323933},
    {0.2516605407371642, 0.6775232436837668, 2.494026599312351},
    {8.353717279216625, -3.577719514958484, 0.3144679030132573},
    {-27.66873308576866, 14.26473078096533, -13.64921318813922},
    {52.17613981234068, -27.94360607168351, 12.94416944238394},
    {-50.76852536473588, 29.04658282127291, 4.23415299384598},
    {18.65570506591883, -11.48977351997711, -5.601961508734096},
}};

constexpr Polynomial kViridis{{
    {0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
    {0.1050930431085774, 1.404613529898575, 1.384590162594685},
    {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
    {-4.634230498983486, -5.799100973351585, -19.33244095627987},
    {6.228269936347081, 14.17993336680509, 56.69055260068105},
    {4.776384997670288, -13.74514537774601, -65.35303263337234},
    {-5.435455855934631, 4.645852612178535, 26.3124352495832},
}};

// The colours of four map values at once (GCC/Clang vector extensions), each value's in its
// own lane: clamped to [0,1] in double (NaN to 0), the polynomial by Horner's rule, then the
// float colour clamped to [0,1] (the fits overshoot it by a few 1e-3 at the ends). No lane
// depends on another, and the baseline x86-64 target has no fused multiply-add to contract
// into, so a value's colour is the same in any lane and on any processor.
using Double4 = double __attribute__((vector_size(32)));
using Float4 = float __attribute__((vector_size(16)));

[[gnu::always_inline]] inline void colours_of_4(const Polynomial& c, const float* t,
                                                glm::vec3* out) {
  const Float4 v = {t[0], t[1], t[2], t[3]};
  Double4 x = __builtin_convertvector(v, Double4);
  x = x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0;  // NaN fails both: 0
  for (int channel = 0; channel < 3; ++channel) {
    Double4 value = Double4{} + c[6][channel];
    for (int i = 5; i >= 0; --i) value = c[i][channel] + x * value;
    Float4 f = __builtin_convertvector(value, Float4);
    f = f < 0.0f ? 0.0f : (1.0f < f ? 1.0f : f);
    for (int lane = 0; lane < 4; ++lane) out[lane][channel] = f[lane];
  }
}

void colour_quads(const Polynomial& c, const float* t, glm::vec3* out, std::size_t quads) {
  for (std::size_t q = 0; q < quads; ++q) colours_of_4(c, t + 4 * q, out + 4 * q);
}

// The same operations with a Double4 in one register instead of two (no FMA in target "avx"):
// the false colour of a frame's FLIP map took 7% of measuring a sweep's frame.
[[gnu::target("avx")]] void colour_quads_avx(const Polynomial& c, const float* t, glm::vec3* out,
                                             std::size_t quads) {
  for (std::size_t q = 0; q < quads; ++q) colours_of_4(c, t + 4 * q, out + 4 * q);
}

const Polynomial& polynomial(ColorMap map) {
  return map == ColorMap::kMagma ? kMagma : kViridis;
}

}  // namespace

glm::vec3 color_map(ColorMap map, float t) {
  const float values[4] = {t, 0.0f, 0.0f, 0.0f};
  glm::vec3 colours[4];
  colours_of_4(polynomial(map), values, colours);
  return colours[0];
}

image::Image false_colour(const image::ScalarMap& map, ColorMap colors) {
  if (map.width <= 0 || map.height <= 0 ||
      map.values.size() != static_cast<std::size_t>(map.width) * map.height) {
    throw QualityError("false_colour: map of " + std::to_string(map.width) + "x" +
                       std::to_string(map.height) + " holds " + std::to_string(map.values.size()) +
                       " values");
  }
  image::Image image;
  image.width = map.width;
  image.height = map.height;
  image.rgb.resize(map.values.size());
  const std::size_t quads = map.values.size() / 4;
  const bool avx = use_avx();
  for_each_block(quads, [&](std::size_t begin, std::size_t end) {
    const float* t = &map.values[begin * 4];
    glm::vec3* out = &image.rgb[begin * 4];
    if (avx) {
      colour_quads_avx(polynomial(colors), t, out, end - begin);
    } else {
      colour_quads(polynomial(colors), t, out, end - begin);
    }
  });
  for (std::size_t i = quads * 4; i < map.values.size(); ++i) {
    image.rgb[i] = color_map(colors, map.values[i]);
  }
  return image;
}

}  // namespace skinsim::quality

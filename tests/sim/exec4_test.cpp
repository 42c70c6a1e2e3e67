// The four-fragment language (Exec4) computes, lane by lane, what Exec computes for each
// fragment alone, bit for bit: its arithmetic and built-in functions on ordinary and special
// values (NaN, infinities, signed zeros, denormals), and its texture unit's values, counters
// and cache-line requests for batches of one to four fragments.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "sim/shader_io.h"
#include "sim/texture.h"
#include "util/simd_dispatch.h"

namespace skinsim::sim {
namespace {

using sl::Lanes;

std::uint32_t bits(float f) {
  return std::bit_cast<std::uint32_t>(f);
}

// Values to compute on: special ones first, then random ones of both signs and wide range.
std::vector<float> operands() {
  std::vector<float> v = {0.0f,
                          -0.0f,
                          1.0f,
                          -1.0f,
                          0.5f,
                          std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::denorm_min(),
                          1e-30f,
                          3e38f};
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> mantissa(-2.0f, 2.0f);
  std::uniform_int_distribution<int> exponent(-20, 20);
  while (v.size() < 64) v.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  return v;
}

// A three-component value from operands i, i + 1, i + 2 (wrapping).
glm::vec3 vec_at(const std::vector<float>& v, std::size_t i) {
  return {v[i % v.size()], v[(i + 1) % v.size()], v[(i + 2) % v.size()]};
}

// Four vectors as lanes, each component written whole.
Lanes<3> lanes_of(const std::array<glm::vec3, 4>& v) {
  Lanes<3> r;
  for (int i = 0; i < 3; ++i) r.c[i] = Float4{v[0][i], v[1][i], v[2][i], v[3][i]};
  return r;
}

// f over Exec's types (float, glm::vec3) against f over Lanes, four operand triples a time.
template <class Fn>
void expect_lanes_match(const char* what, Fn fn) {
  const std::vector<float> v = operands();
  for (std::size_t first = 0; first < v.size(); first += 4) {
    std::array<glm::vec3, 4> ea, eb;
    std::array<float, 4> es;
    for (int l = 0; l < 4; ++l) {
      ea[l] = vec_at(v, first + l);
      eb[l] = vec_at(v, first + l + 7);
      es[l] = v[(first + l + 13) % v.size()];
    }
    const Lanes<3> a = lanes_of(ea), b = lanes_of(eb);
    Lanes<1> s;
    s.c[0] = Float4{es[0], es[1], es[2], es[3]};
    const auto lanes = fn(a, b, s);
    for (int l = 0; l < 4; ++l) {
      const auto exec = fn(ea[l], eb[l], es[l]);
      const auto got = lanes.lane(l);
      if constexpr (std::is_same_v<decltype(exec), const float>) {
        ASSERT_EQ(bits(got), bits(exec)) << what << " lane " << l << " at " << first;
      } else {
        for (int c = 0; c < exec.length(); ++c) {
          ASSERT_EQ(bits(got[c]), bits(exec[c])) << what << " lane " << l << " at " << first;
        }
      }
    }
  }
}

TEST(Exec4, ArithmeticAndFunctionsAreExecLaneByLane) {
  expect_lanes_match("a + b * s - a / s", [](auto a, auto b, auto s) { return a + b * s - a / s; });
  expect_lanes_match("-a * b", [](auto a, auto b, auto) { return -a * b; });
  expect_lanes_match("dot", [](auto a, auto b, auto) { return sl::dot(a, b); });
  expect_lanes_match("normalize", [](auto a, auto, auto) { return sl::normalize(a); });
  expect_lanes_match("length", [](auto a, auto, auto) { return sl::length(a); });
  expect_lanes_match("cross", [](auto a, auto b, auto) { return sl::cross(a, b); });
  expect_lanes_match("saturate", [](auto a, auto, auto) { return sl::saturate(a); });
  expect_lanes_match("saturate scalar", [](auto, auto, auto s) { return sl::saturate(s); });
  expect_lanes_match("abs", [](auto a, auto, auto) { return sl::abs(a); });
  expect_lanes_match("abs scalar", [](auto, auto, auto s) { return sl::abs(s); });
  expect_lanes_match("min max",
                     [](auto a, auto b, auto s) { return sl::min(sl::max(a, b), s + 0.0f); });
  expect_lanes_match("step", [](auto a, auto b, auto) { return sl::step(a, b); });
  expect_lanes_match("clamp", [](auto a, auto, auto) { return sl::clamp(a, 0.25f, 0.75f); });
  expect_lanes_match("mix", [](auto a, auto b, auto s) { return sl::mix(a, b, s); });
  expect_lanes_match("pow", [](auto a, auto, auto s) { return sl::pow(sl::abs(a), s); });
  expect_lanes_match("exp", [](auto a, auto, auto) { return sl::exp(a); });
  expect_lanes_match("rsqrt rcp", [](auto a, auto, auto) { return sl::rsqrt(a) + sl::rcp(a); });
  expect_lanes_match("sin cos", [](auto a, auto, auto) { return sl::sin(a) * sl::cos(a); });
  expect_lanes_match("fract", [](auto a, auto, auto) { return sl::fract(a); });
  expect_lanes_match("reflect", [](auto a, auto b, auto) { return sl::reflect(a, b); });
  expect_lanes_match("select", [](auto a, auto b, auto s) { return sl::select(s, a, b); });
  expect_lanes_match("components", [](auto a, auto b, auto) {
    using V3 = decltype(a);
    return V3(sl::z(a), sl::x(b), sl::y(a) * 2.0f);
  });
}

// Batches of one to four fragments read through Exec4TexUnit (2D and cube reads, independent
// and dependent, and shadow-map comparisons) give each fragment what ExecTexUnit gives it alone,
// and the tile's log holds their requests in fragment order. Over nearest, bilinear and trilinear
// textures, with and without mip chains, both texel sizes and both wraps; at coordinates inside,
// across the borders and far outside; with derivatives from magnification to several levels down;
// in the AVX2 path and the baseline.
TEST(Exec4, TextureReadsAreExecFragmentByFragment) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> near(-0.3f, 1.3f);
  std::uniform_real_distribution<float> log_scale(-9.0f, 0.0f);
  std::vector<std::array<Varying<2>, 4>> batches(60);
  for (auto& batch : batches) {
    for (Varying<2>& uv : batch) {
      uv.value = {near(rng), near(rng)};
      uv.ddx = {std::exp2(log_scale(rng)), 0.0f};
      uv.ddy = {0.0f, std::exp2(log_scale(rng))};
    }
  }
  batches[0][1].value = {std::nanf(""), 0.5f};
  batches[0][2].value = {-7.25f, 1e9f};
  std::vector<glm::vec4> texels(48 * 32);
  for (glm::vec4& t : texels) t = glm::vec4(near(rng), near(rng), near(rng), near(rng));
  std::array<std::vector<glm::vec4>, 6> faces;
  for (std::vector<glm::vec4>& face : faces) {
    face.assign(texels.begin(), texels.begin() + 16 * 16);
    std::shuffle(face.begin(), face.end(), rng);
  }
  std::uniform_real_distribution<float> signed_unit(-1.0f, 1.0f);
  for (const Filter filter : {Filter::kNearest, Filter::kBilinear, Filter::kTrilinear}) {
    for (const TexelFormat format : {TexelFormat::kRGBA8, TexelFormat::kRGBA16F}) {
      for (const Wrap wrap : {Wrap::kClamp, Wrap::kRepeat}) {
        for (const bool mipmaps : {false, true}) {
          const Texture2D t("t", 48, 32, texels, format, {filter, wrap}, mipmaps);
          const TextureCube cube("c", 16, faces, format, {filter, wrap}, mipmaps);
          TextureBindings b;
          b.textures[3] = &t;
          b.cubes[5] = &cube;
          for (const bool baseline : {false, true}) {
            std::optional<BaselineSimdScope> scope;
            if (baseline) scope.emplace();
            TextureLineLog lanes_lines(64), one_lines(64);
            TextureCounters lanes_counters, one_counters;
            ExecTexUnit lanes_unit(&lanes_lines, &lanes_counters), one(&one_lines, &one_counters);
            lanes_unit.bind(&b);
            one.bind(&b);
            Exec4TexUnit unit4(lanes_unit, 64);
            int n = 0;
            for (const auto& batch : batches) {
              n = n % 4 + 1;
              Varying4<2> uv;
              Lanes<1> lod;
              for (int l = 0; l < 4; ++l) {
                uv.value.set_lane(l, batch[l].value);
                uv.ddx.set_lane(l, batch[l].ddx);
                uv.ddy.set_lane(l, batch[l].ddy);
                lod.set_lane(l, log_scale(rng) + 9.0f);
              }
              // Shadow-map coordinates: (u, v) and a depth to compare with.
              Varying4<3> shadow;
              shadow.value = Lanes<3>(sl::x(uv.value), sl::y(uv.value), lod * (1.0f / 9.0f));
              // Directions into the cube, with derivatives from the same scales.
              Varying4<3> direction;
              for (int l = 0; l < 4; ++l) {
                direction.value.set_lane(
                    l, glm::vec3(signed_unit(rng), signed_unit(rng), signed_unit(rng)));
                direction.ddx.set_lane(l, glm::vec3(batch[l].ddx, 0.0f));
                direction.ddy.set_lane(l, glm::vec3(0.0f, batch[l].ddy));
              }
              unit4.begin(n);
              const Lanes<4> independent = unit4.sample(3, uv);
              const Lanes<4> dependent = unit4.sample_lod(3, uv.value, lod);
              const Lanes<1> lit = unit4.sample_shadow(3, shadow);
              const Lanes<1> lit_dependent = unit4.sample_shadow(3, shadow.value);
              const Lanes<4> env = unit4.sample_cube(5, direction);
              const Lanes<4> env_lod = unit4.sample_cube_lod(5, direction.value, lod);
              unit4.end();
              for (int l = 0; l < n; ++l) {
                const glm::vec4 a = one.sample(3, batch[l]);
                const glm::vec4 d = one.sample_lod(3, batch[l].value, lod.lane(l));
                Varying<3> shadow_at;
                shadow_at.value = shadow.value.lane(l);
                const float s = one.sample_shadow(3, shadow_at);
                const float sd = one.sample_shadow(3, shadow_at.value);
                const glm::vec4 e = one.sample_cube(5, direction.lane(l));
                const glm::vec4 el = one.sample_cube_lod(5, direction.value.lane(l), lod.lane(l));
                for (int c = 0; c < 4; ++c) {
                  ASSERT_EQ(bits(independent.lane(l)[c]), bits(a[c])) << "lane " << l;
                  ASSERT_EQ(bits(dependent.lane(l)[c]), bits(d[c])) << "lane " << l;
                  ASSERT_EQ(bits(env.lane(l)[c]), bits(e[c])) << "lane " << l;
                  ASSERT_EQ(bits(env_lod.lane(l)[c]), bits(el[c])) << "lane " << l;
                }
                ASSERT_EQ(bits(lit.lane(l)), bits(s)) << "lane " << l;
                ASSERT_EQ(bits(lit_dependent.lane(l)), bits(sd)) << "lane " << l;
              }
            }
            EXPECT_EQ(lanes_lines.lines(), one_lines.lines());
            EXPECT_EQ(lanes_counters.texels_touched, one_counters.texels_touched);
            EXPECT_EQ(lanes_counters.cache_line_accesses, one_counters.cache_line_accesses);
            for (int f = 0; f < kFilterCount; ++f) {
              EXPECT_EQ(lanes_counters.samples_by_filter[f], one_counters.samples_by_filter[f]);
            }
            EXPECT_EQ(lanes_counters.samples_wide_format, one_counters.samples_wide_format);
            EXPECT_EQ(lanes_counters.samples_dependent, one_counters.samples_dependent);
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace skinsim::sim

// Shader precision: FP16 rounding, mediump programs computing in FP16, their ops counted as
// mediump, and their GLSL stating it.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "shading/fp16.h"
#include "tests/sim/test_shaders.h"

namespace skinsim::sim {
namespace {

// The arithmetic definition round_to_fp16 must match: the nearest multiple of the half's
// unit in the last place at the value's binade, ties to even, saturating at 65504.
float fp16_by_definition(float v) {
  if (!std::isfinite(v)) return v;
  const float a = std::fabs(v);
  if (a >= 65504.0f) return std::copysign(65504.0f, v);
  if (a < 6.103515625e-05f) return std::copysign(std::nearbyint(a * 16777216.0f) / 16777216.0f, v);
  int exponent = 0;
  std::frexp(a, &exponent);
  const float step = std::ldexp(1.0f, exponent - 11);
  return std::copysign(std::nearbyint(a / step) * step, v);
}

TEST(Fp16, MatchesTheDefinitionAcrossTheFloats) {
  // Every 251st bit pattern (17 million floats of every sign, binade and NaN payload) plus
  // both neighbours of every pattern there, so ties and carries are hit; the full 2^32
  // sweep also passes but takes half a minute.
  int mismatches = 0;
  for (std::uint64_t i = 0; i <= 0xFFFFFFFFull; i += 251) {
    for (std::uint64_t j = i == 0 ? i : i - 1; j <= std::min<std::uint64_t>(i + 1, 0xFFFFFFFFull);
         ++j) {
      const float v = std::bit_cast<float>(static_cast<std::uint32_t>(j));
      const float want = fp16_by_definition(v), got = round_to_fp16(v);
      const bool same = std::bit_cast<std::uint32_t>(want) == std::bit_cast<std::uint32_t>(got) ||
                        (std::isnan(want) && std::isnan(got));
      if (!same && ++mismatches <= 5) ADD_FAILURE() << v << ": " << got << " != " << want;
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(Fp16, RoundsTiesToEvenAndKeepsSubnormalsAndSaturates) {
  EXPECT_EQ(round_to_fp16(1.0f + 1.0f / 2048), 1.0f);                // tie, even stays
  EXPECT_EQ(round_to_fp16(1.0f + 3.0f / 2048), 1.0f + 4.0f / 2048);  // tie, odd rounds up
  EXPECT_EQ(round_to_fp16(2049.0f), 2048.0f);
  EXPECT_EQ(round_to_fp16(3.0e-7f), 5.0f / 16777216.0f);  // subnormal half
  EXPECT_EQ(round_to_fp16(1.0e5f), 65504.0f);
  EXPECT_EQ(round_to_fp16(-1.0e5f), -65504.0f);
  EXPECT_TRUE(std::isinf(round_to_fp16(INFINITY)));
  EXPECT_TRUE(std::signbit(round_to_fp16(-1.0e-9f)));
}

// One MAD on a varying: at mediump, 1 + 1/4096 is not representable.
struct AddSmallFS {
  static constexpr const char* kName = "test_add_small_fs";
  struct Uniforms {
    float small = 1.0f / 4096;
  };
  template <class L>
  static typename L::vec4 fragment(const typename L::FragIn& in, typename L::TexUnit&,
                                   const Uniforms& u) {
    const typename L::f32 x = in.f(0);
    return typename L::vec4(x * 2.0f + u.small, x, x, 1.0f);
  }
};

glm::vec4 shade_at(const FragmentProgram& fs, float varying) {
  Plane planes[kMaxVaryings] = {};
  planes[0].c = varying;
  const Plane inv_w{1.0f, 0.0f, 0.0f};
  const ExecFragIn in(planes, inv_w, 0.0f, 0.0f, glm::vec2(0.5f), glm::vec2(1.0f));
  ExecTexUnit tex(nullptr, nullptr);
  return fs.shade(in, tex);
}

TEST(ShaderPrecision, MediumpProgramsComputeInFp16) {
  const auto highp = make_fragment_program<AddSmallFS>({});
  const auto mediump = make_fragment_program<AddSmallFS>({}, Precision::kMediump);
  EXPECT_EQ(highp->name(), "test_add_small_fs");
  EXPECT_EQ(mediump->name(), "test_add_small_fs_mediump");
  EXPECT_EQ(shade_at(*highp, 0.5f).x, 1.0f + 1.0f / 4096);
  EXPECT_EQ(shade_at(*mediump, 0.5f).x, 1.0f);
  // The varying itself is read at mediump: 0.1 becomes its nearest half.
  EXPECT_EQ(shade_at(*mediump, 0.1f).y, round_to_fp16(0.1f));
  EXPECT_EQ(shade_at(*highp, 0.1f).y, 0.1f);
}

TEST(ShaderPrecision, MediumpOpsAreCountedAsMediump) {
  const OpProfile highp = make_fragment_program<testing::ProfileProbeFS>({})->profile();
  const OpProfile mediump =
      make_fragment_program<testing::ProfileProbeFS>({}, Precision::kMediump)->profile();
  EXPECT_EQ(highp.vector_ops_mediump + highp.scalar_ops_mediump + highp.transcendental_ops_mediump,
            0u);
  // The same ops, all of them at mediump.
  EXPECT_EQ(mediump.vector_ops, highp.vector_ops);
  EXPECT_EQ(mediump.vector_ops_mediump, highp.vector_ops);
  EXPECT_EQ(mediump.scalar_ops_mediump, highp.scalar_ops);
  EXPECT_EQ(mediump.transcendental_ops_mediump, highp.transcendental_ops);
  EXPECT_EQ(mediump.texture_reads(), highp.texture_reads());
}

TEST(ShaderPrecision, MediumpSourceStatesItsDefaultPrecision) {
  const auto mediump = make_fragment_program<AddSmallFS>({}, Precision::kMediump);
  const auto highp = make_fragment_program<AddSmallFS>({});
  for (const auto dialect : {sl::GlslDialect::kEs100, sl::GlslDialect::kEs300}) {
    EXPECT_NE(mediump->glsl(dialect).source.find("precision mediump float;\n"), std::string::npos);
    EXPECT_EQ(mediump->glsl(dialect).source.find("highp"), std::string::npos);
    EXPECT_NE(highp->glsl(dialect).source.find("precision highp float;\n"), std::string::npos);
  }
}

}  // namespace
}  // namespace skinsim::sim

// Op profiles come from the shader's own code.
#include <gtest/gtest.h>

#include "tests/sim/test_shaders.h"

namespace skinsim::sim {
namespace {

TEST(ShaderProfile, CountsOpsAndTextureReadKindsFromTheCode) {
  const auto fs = make_fragment_program<testing::ProfileProbeFS>({});
  const OpProfile& p = fs->profile();
  EXPECT_EQ(p.texture_reads_independent, 1u);
  EXPECT_EQ(p.texture_reads_dependent, 1u);
  // normalize = dot + rsqrt + mul; dot(n, l); xy*0.5+0.25 (MAD); base*ndotl+lut (MAD).
  EXPECT_EQ(p.vector_ops, 5u);
  EXPECT_EQ(p.scalar_ops, 1u);  // saturate of a scalar
  EXPECT_EQ(p.transcendental_ops, 1u);
  EXPECT_EQ(p.input_floats, 5u);
}

TEST(ShaderProfile, ConstantExpressionsAreFolded) {
  const auto fs = make_fragment_program<testing::FlatColorFS>({glm::vec4(0.5f)});
  EXPECT_EQ(fs->profile().alu_ops(), 0u);
  EXPECT_EQ(fs->profile().texture_reads(), 0u);
}

TEST(ShaderProfile, VertexProgramReportsVaryings) {
  const auto vs = make_vertex_program<testing::PassThroughVS>({});
  EXPECT_EQ(vs->varying_floats(), 2);
  EXPECT_EQ(vs->profile().output_floats, 6u);
}

TEST(ShaderProfile, FusesMultiplyAddAndCountsDivisionAsReciprocal) {
  using sl::CVec;
  OpProfile p;
  {
    sl::OpRecorder rec(&p);
    const auto a = CVec<3>::computed(glm::vec3(1.0f));
    const auto b = CVec<3>::computed(glm::vec3(2.0f));
    const auto s = sl::CFloat::computed(glm::vec1(4.0f));
    const auto mad = a * b + a;  // 1 vector op
    const auto div = mad / s;    // rcp + mul
    EXPECT_EQ(div.v, glm::vec3(0.75f));
  }
  EXPECT_EQ(p.vector_ops, 2u);
  EXPECT_EQ(p.transcendental_ops, 1u);
}

}  // namespace
}  // namespace skinsim::sim

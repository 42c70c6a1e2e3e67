#include "shading/shader_emit.h"

#include <gtest/gtest.h>

namespace skinsim::sim::sl {
namespace {

// A small Lambert-like body, written the way pipeline/shaders/ write theirs.
TEST(ShaderEmit, SmallShaderEmitsOneNamedStatementPerOperation) {
  GlslEmitter emitter;
  const EVec<3> normal = EVec<3>::named("v_slot0");
  const EVec<3> light(glm::vec3(0.0f, 0.0f, 1.0f));
  const EFloat n_dot_l = saturate(dot(normal, light));
  const EVec<3> colour = EVec<3>(glm::vec3(0.5f, 0.25f, 1.0f)) * n_dot_l + 0.125f;
  GlslEmitter::statement("gl_FragColor = vec4(" + colour.expr + ", 1.0);");
  EXPECT_EQ(emitter.body(),
            "  float t0 = dot(v_slot0, vec3(0.0, 0.0, 1.0));\n"
            "  float t1 = clamp(t0, 0.0, 1.0);\n"
            "  vec3 t2 = vec3(0.5, 0.25, 1.0) * t1;\n"
            "  vec3 t3 = t2 + 0.125;\n"
            "  gl_FragColor = vec4(t3, 1.0);\n");
}

TEST(ShaderEmit, OperationsOnConstantsFoldToLiterals) {
  GlslEmitter emitter;
  const EFloat roughness(0.5f);
  const EFloat folded = exp2(roughness * 2.0f + 1.0f);  // exp2(2.0) = 4.0, emitted as a literal
  EXPECT_TRUE(folded.constant);
  EXPECT_EQ(folded.expr, "4.0");
  const EVec<3> splat = max(EVec<3>(glm::vec3(-1.0f)), 0.0f);
  EXPECT_EQ(splat.expr, "vec3(0.0)");
  EXPECT_EQ(emitter.body(), "");  // nothing computed at run time
}

TEST(ShaderEmit, NegationAndSwizzlesAreModifiersNotStatements) {
  GlslEmitter emitter;
  const EVec<4> position = EVec<4>::named("a_position");
  const EFloat depth = -z(position);
  EXPECT_EQ(depth.expr, "-a_position.z");
  EXPECT_EQ((-depth).expr, "a_position.z");  // never "--", GLSL's decrement
  EXPECT_EQ(emitter.body(), "");
}

TEST(ShaderEmit, ScalarFirstOperandOfMinIsSplatForGlsl) {
  GlslEmitter emitter;
  const EVec<2> uv = EVec<2>::named("v_slot1");
  const EVec<2> clamped = min(EFloat::named("u_limit"), uv);
  EXPECT_EQ(clamped.expr, "t0");
  EXPECT_EQ(emitter.body(), "  vec2 t0 = min(vec2(u_limit), v_slot1);\n");
}

TEST(ShaderEmit, SelectFoldsOnlyWhenEveryOperandIsConstantAsCountDoes) {
  GlslEmitter emitter;
  EXPECT_EQ(select(EFloat(1.0f), EFloat(2.0f), EFloat(3.0f)).expr, "2.0");
  const EFloat picked = select(EFloat(1.0f), EFloat::named("v_slot0"), EFloat(3.0f));
  EXPECT_EQ(emitter.body(), "  float t0 = 1.0 > 0.0 ? v_slot0 : 3.0;\n");
  EXPECT_EQ(picked.expr, "t0");
}

TEST(ShaderEmit, UniformMatrixIsInlinedColumnMajor) {
  GlslEmitter emitter;
  glm::mat3 m(1.0f);
  m[2][0] = 5.0f;  // column 2, row 0
  const EVec<3> moved = m * EVec<3>::named("a_normal");
  EXPECT_EQ(emitter.body(),
            "  vec3 t0 = mat3(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 5.0, 0.0, 1.0) * a_normal;\n");
  EXPECT_EQ((m * EVec<3>(glm::vec3(0.0f, 0.0f, 1.0f))).expr, "vec3(5.0, 0.0, 1.0)");
  EXPECT_EQ(moved.expr, "t0");
}

TEST(ShaderEmit, FloatLiteralsReadBackExactlyAndAlwaysHaveAPoint) {
  const struct {
    float value;
    const char* glsl;
  } cases[] = {
      {0.0f, "0.0"},   {1.0f, "1.0"}, {-2.0f, "-2.0"}, {0.1f, "0.1"}, {1.0f / 3.0f, "0.33333334"},
      {1e20f, "1e+20"}};
  for (const auto& c : cases) EXPECT_EQ(glsl_float(c.value), c.glsl) << c.value;
}

}  // namespace
}  // namespace skinsim::sim::sl

// Emitted bodies compile with Khronos' reference compiler, as GLSL ES 1.00 and 3.00.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "pipeline/shaders/gamma.h"
#include "shading/shader_emit.h"
#include "shading/shader_lang.h"

namespace skinsim::sim::sl {
namespace {

// A specular-like body through the language's shared helpers (normalize, reflect,
// pow, mix, clamp are written once over any value type), so the compiler sees what
// they expand to.
std::string specular_body() {
  GlslEmitter emitter;
  const EVec<3> normal = normalize(EVec<3>::named("v_slot0"));
  const EVec<3> view = normalize(EVec<3>::named("v_slot1"));
  const EVec<3> light(glm::vec3(0.0f, 0.6f, 0.8f));
  const EVec<3> r = reflect(-light, normal);
  const EFloat highlight = pow(clamp(dot(r, view), 0.0f, 1.0f), EFloat(32.0f));
  const EVec<3> albedo = mix(EVec<3>(glm::vec3(0.8f, 0.5f, 0.4f)), normal, EFloat(0.25f));
  const EVec<3> colour = albedo * max(dot(normal, light), 0.0f) + highlight;
  GlslEmitter::statement("frag_colour = vec4(" + colour.expr + ", 1.0);");
  return emitter.body();
}

std::string fragment_shader(bool es3, const std::string& body) {
  std::string s = es3 ? "#version 300 es\nprecision highp float;\n"
                        "in vec3 v_slot0;\nin vec3 v_slot1;\nout vec4 frag_colour;\n"
                      : "#version 100\nprecision highp float;\n"
                        "varying vec3 v_slot0;\nvarying vec3 v_slot1;\n"
                        "#define frag_colour gl_FragColor\n";
  return s + "void main() {\n" + body + "}\n";
}

// Writes each variant of `body` to a file and runs the reference compiler on it.
void expect_compiles(const std::string& name, const std::string& body) {
  const std::string validator = SKINSIM_GLSLANG_VALIDATOR;
  ASSERT_FALSE(validator.empty()) << "glslangValidator not found: install glslang-tools";
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "emit_validate";
  std::filesystem::create_directories(dir);
  for (const bool es3 : {false, true}) {
    const std::filesystem::path file = dir / (name + (es3 ? "_es300.frag" : "_es100.frag"));
    std::ofstream(file) << fragment_shader(es3, body);
    const std::string command =
        validator + " " + file.string() + " > " + (dir / "log.txt").string() + " 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0)
        << fragment_shader(es3, body) << std::ifstream(dir / "log.txt").rdbuf();
  }
}

TEST(ShaderEmitValidate, SpecularBodyCompilesAsGlslEs100And300) {
  expect_compiles("specular", specular_body());
}

// Real pipeline shader code (the sRGB curves of pipeline/shaders/gamma.h), unchanged.
TEST(ShaderEmitValidate, PipelineGammaCurvesCompileAsGlslEs100And300) {
  namespace shaders = pipeline::shaders;
  GlslEmitter emitter;
  const EVec<3> linear =
      shaders::decode_gamma<pipeline::GammaMode::kSrgb>(EVec<3>::named("v_slot0"));
  const EVec<3> encoded = shaders::encode_gamma<pipeline::GammaMode::kSrgb>(linear);
  GlslEmitter::statement("frag_colour = vec4(" + encoded.expr + ", 1.0);");
  expect_compiles("gamma", emitter.body());
}

}  // namespace
}  // namespace skinsim::sim::sl

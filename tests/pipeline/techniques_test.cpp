// Every comparison technique renders a small frame of a small head on the emulated GPU:
// its passes are the designed ones, it shades the skin, and its shaders read textures the
// intended way (independent vs dependent).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/pipeline/small_frames.h"

namespace skinsim::pipeline {
namespace {

using testing::centre_mean;
using testing::render;
using testing::skin_draw;
using testing::small_config;

std::vector<std::string> pass_names(const FrameOutput& out) {
  std::vector<std::string> names;
  for (const auto& p : out.passes) names.push_back(p.name);
  return names;
}

struct Expected {
  std::string technique;
  std::vector<std::string> passes;
  std::string skin_program;
  std::uint32_t independent;
  std::uint32_t dependent;
};

class TechniqueFrame : public ::testing::TestWithParam<Expected> {};

TEST_P(TechniqueFrame, PassesShadingAndReads) {
  const Expected& e = GetParam();
  const FrameOutput out = render(small_config(e.technique));
  EXPECT_EQ(pass_names(out), e.passes);
  const sim::DrawCounters& skin = skin_draw(out);
  EXPECT_EQ(skin.fragment_program, e.skin_program);
  EXPECT_GT(skin.fragments_shaded, 256u * 192u / 8u) << "skin covers a good part of the frame";
  EXPECT_EQ(skin.fragment_profile.texture_reads_independent, e.independent);
  EXPECT_EQ(skin.fragment_profile.texture_reads_dependent, e.dependent);
  // Skin lit by a white key light: bright, and red above green above blue.
  const glm::vec3 face = centre_mean(out.frame);
  EXPECT_GT(face.r, 0.25f);
  EXPECT_GT(face.r, face.g);
  EXPECT_GT(face.g, face.b);
}

INSTANTIATE_TEST_SUITE_P(
    All, TechniqueFrame,
    ::testing::Values(
        // The built-in head's lights: a shadowed key light and a back light. Every skin
        // pass reads albedo, normal, environment and the key light's shadow map (four
        // hardware-PCF fetches: one from a varying, three dependent), and per light the BRDF
        // LUT.
        // preintegrated: + curvature; 3 pre-integrated LUT reads per light + the penumbra LUT
        Expected{"preintegrated", {"shadow", "skin"}, "preintegrated_fs", 5, 12},
        Expected{"wrap", {"shadow", "skin"}, "wrap_fs", 4, 5},
        Expected{"burley", {"shadow", "diffuse", "sss", "skin"}, "diffused_skin_fs", 5, 5},
        Expected{"ssss", {"shadow", "diffuse", "sss_h", "sss_v", "skin"}, "diffused_skin_fs", 5, 5},
        Expected{"dipole", {"shadow", "diffuse", "sss", "skin"}, "diffused_skin_fs", 5, 5},
        // urp: albedo, normal, shadow, baked AO (uv) and the SSAO (at the pixel); the normal
        // map's blurred mip, the detail map twice, 3 LUT reads per light, 3 environment reads.
        Expected{
            "urp", {"shadow", "depth_normal", "ssao", "ssao_h", "ssao_v", "skin"}, "urp_fs", 5, 15},
        Expected{"texture-space",
                 {"shadow", "uv_irradiance", "uv_blur_1_h", "uv_blur_1_v", "uv_blur_2_h",
                  "uv_blur_2_v", "uv_blur_3_h", "uv_blur_3_v", "uv_blur_4_h", "uv_blur_4_v",
                  "uv_blur_5_h", "uv_blur_5_v", "uv_combine", "skin"},
                 "uv_diffused_skin_fs",
                 5,
                 5}),
    [](const ::testing::TestParamInfo<Expected>& param) {
      std::string name = param.param.technique;
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

const sim::DrawCounters& draw_named(const FrameOutput& out, const std::string& pass) {
  for (const auto& p : out.passes) {
    if (p.name == pass) return p.draws.at(0);
  }
  throw std::runtime_error("no pass " + pass);
}

TEST(TechniqueReads, BurleyTapsAreDependentAndFollowTheSampleCount) {
  PipelineConfig c = small_config("burley");
  set_config_field(c, "burley_samples", "12");
  const FrameOutput out = render(c);
  const sim::OpProfile& p = draw_named(out, "sss").fragment_profile;
  EXPECT_EQ(p.texture_reads_independent, 1u);  // the centre
  EXPECT_EQ(p.texture_reads_dependent, 12u);
}

TEST(TechniqueReads, DipoleEvaluatesTheProfileAtEveryTap) {
  const auto sss = [](const std::string& samples) {
    PipelineConfig c = small_config("dipole");
    set_config_field(c, "dipole_samples", samples);
    return draw_named(render(c), "sss").fragment_profile;
  };
  const sim::OpProfile p12 = sss("12"), p13 = sss("13");
  EXPECT_EQ(p12.texture_reads_independent, 1u);  // the centre
  EXPECT_EQ(p12.texture_reads_dependent, 11u);
  // Each tap evaluates R_d in the shader: two poles, each an rsqrt and an exp2 per channel.
  EXPECT_EQ(p13.transcendental_ops - p12.transcendental_ops, 12u);
  EXPECT_GT(p13.vector_ops - p12.vector_ops, 15u);
}

TEST(TechniqueReads, SsssAxisHasSixteenDependentTaps) {
  const FrameOutput out = render(small_config("ssss"));
  for (const char* pass : {"sss_h", "sss_v"}) {
    const sim::OpProfile& p = draw_named(out, pass).fragment_profile;
    EXPECT_EQ(p.texture_reads_independent, 1u) << pass;
    EXPECT_EQ(p.texture_reads_dependent, 16u) << pass;
  }
}

TEST(TechniqueReads, DerivativeCurvatureReplacesTheCurvatureTexture) {
  PipelineConfig c = small_config("preintegrated");
  set_config_field(c, "curvature", "derivatives");
  const FrameOutput out = render(c);
  const sim::DrawCounters& skin = skin_draw(out);
  EXPECT_EQ(skin.fragment_program, "preintegrated_fs_derivatives");
  EXPECT_EQ(skin.fragment_profile.texture_reads_independent, 4u);
  EXPECT_EQ(skin.fragment_profile.texture_reads_dependent, 12u);
}

TEST(TechniqueCost, TextureSpaceTrafficGrowsWithTheTextureSize) {
  const auto traffic = [](const std::string& size) {
    PipelineConfig c = small_config("texture-space");
    set_config_field(c, "texture_space_size", size);
    const FrameOutput out = render(c);
    std::uint64_t bytes = 0;
    for (const auto& p : out.passes) {
      if (p.name != "skin") bytes += p.color_store_bytes + p.texture.dram_bytes;
    }
    return bytes;
  };
  const std::uint64_t small = traffic("64"), large = traffic("128");
  EXPECT_GT(large, 3 * small);  // 4x the texels
}

TEST(TechniqueLook, WrapBrightensTheShadowSide) {
  PipelineConfig none = small_config("wrap");
  set_config_field(none, "wrap", "0");
  PipelineConfig full = small_config("wrap");
  set_config_field(full, "wrap", "1");
  const glm::vec3 a = centre_mean(render(none).frame), b = centre_mean(render(full).frame);
  EXPECT_GT(b.r + b.g + b.b, a.r + a.g + a.b);
}

}  // namespace
}  // namespace skinsim::pipeline

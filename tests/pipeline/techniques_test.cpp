// Every technique in the registry renders a small frame of a small head on the emulated GPU:
// it shades the skin, and its skin shader reads textures the intended way (independent vs
// dependent).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "pipeline/technique.h"
#include "tests/pipeline/small_frames.h"

namespace skinsim::pipeline {
namespace {

using testing::centre_mean;
using testing::render;
using testing::skin_draw;
using testing::small_config;

// What each technique's skin shader is and how it reads its textures. The built-in head's
// lights: a shadowed key light and a back light. Every skin pass reads albedo, normal,
// environment and the key light's shadow map (four hardware-PCF fetches: one from a
// varying, three dependent), and per light the BRDF LUT.
struct SkinReads {
  std::string program;
  std::uint32_t independent;
  std::uint32_t dependent;
};
const std::map<std::string, SkinReads> kSkinReads = {
    // mobile: + the blurred irradiance (at the pixel); lod: the single-pass shader, no more.
    {"mobile", {"skin_fs", 5, 5}},
    {"lod", {"skin_lod_fs", 4, 5}},
    // preintegrated: + curvature; 3 pre-integrated LUT reads per light + the penumbra LUT
    {"preintegrated", {"preintegrated_fs", 5, 12}},
    {"wrap", {"wrap_fs", 4, 5}},
    {"burley", {"diffused_skin_fs", 5, 5}},
    {"ssss", {"diffused_skin_fs", 5, 5}},
    {"dipole", {"diffused_skin_fs", 5, 5}},
    // urp: albedo, normal, shadow, baked AO (uv) and the SSAO (at the pixel); the normal
    // map's blurred mip, the detail map twice, 3 LUT reads per light, 3 environment reads.
    {"urp", {"urp_fs", 5, 15}},
    {"texture-space", {"uv_diffused_skin_fs", 5, 5}},
};

// Every technique in the registry (its passes:
// TechniqueConfig.EveryTechniqueRendersThroughItsSpec).
class TechniqueFrame : public ::testing::TestWithParam<std::string> {};

TEST_P(TechniqueFrame, ShadingAndReads) {
  const FrameOutput out = render(small_config(GetParam()));
  const sim::DrawCounters& skin = skin_draw(out);
  const auto row = kSkinReads.find(GetParam());
  ASSERT_NE(row, kSkinReads.end())
      << GetParam() << " has no row in kSkinReads; it ran " << skin.fragment_program << " with "
      << skin.fragment_profile.texture_reads_independent << " independent and "
      << skin.fragment_profile.texture_reads_dependent << " dependent reads";
  const SkinReads& e = row->second;
  EXPECT_EQ(skin.fragment_program, e.program);
  EXPECT_GT(skin.fragments_shaded, 256u * 192u / 8u) << "skin covers a good part of the frame";
  EXPECT_EQ(skin.fragment_profile.texture_reads_independent, e.independent);
  EXPECT_EQ(skin.fragment_profile.texture_reads_dependent, e.dependent);
  // Skin lit by a white key light: bright, and red above green above blue.
  const glm::vec3 face = centre_mean(out.frame);
  EXPECT_GT(face.r, 0.25f);
  EXPECT_GT(face.r, face.g);
  EXPECT_GT(face.g, face.b);
}

INSTANTIATE_TEST_SUITE_P(All, TechniqueFrame, ::testing::ValuesIn(technique_names()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param;
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

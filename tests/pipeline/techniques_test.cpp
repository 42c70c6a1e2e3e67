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
// environment and the key light's shadow map (one hardware-PCF fetch, from a varying), and
// per light the BRDF LUT.
struct SkinReads {
  std::string program;
  std::uint32_t independent;
  std::uint32_t dependent;
};
const std::map<std::string, SkinReads> kSkinReads = {
    // mobile: + the blurred irradiance (at the pixel); lod: the single-pass shader, no more.
    {"mobile", {"skin_fs", 5, 2}},
    {"lod", {"skin_lod_fs", 4, 2}},
    // preintegrated: + curvature; 3 pre-integrated LUT reads per light + the penumbra LUT
    {"preintegrated", {"preintegrated_fs", 5, 9}},
    {"wrap", {"wrap_fs", 4, 2}},
    {"burley", {"diffused_skin_fs", 5, 2}},
    {"ssss", {"diffused_skin_fs", 5, 2}},
    {"dipole", {"diffused_skin_fs", 5, 2}},
    // urp: albedo, normal, shadow, baked AO (uv) and the SSAO (at the pixel); the normal
    // map's blurred mip, the detail map twice, 3 LUT reads per light, 3 environment reads.
    {"urp", {"urp_fs", 5, 12}},
    {"texture-space", {"uv_diffused_skin_fs", 5, 2}},
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

}  // namespace
}  // namespace skinsim::pipeline

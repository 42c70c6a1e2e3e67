// The `specular` knob in the mobile pipeline's shader, its LOD shader and a comparison
// technique's: the analytic models replace the BRDF LUT's dependent read with ALU, make the
// LUT knobs irrelevant, and change the image by plausible amounts, the lobes only where the
// key light's specular is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tests/pipeline/small_frames.h"

namespace skinsim::pipeline {
namespace {

using testing::centre_mean;
using testing::render;
using testing::skin_draw;

constexpr const char* kAnalytic[] = {"ks", "ggx", "dual_ggx"};

// The key light alone (no back light), so that one BRDF LUT read is the whole specular, and
// one shadow tap (its only read from a varying), so that the LUT read is the only dependent one.
PipelineConfig small_config(const std::string& technique) {
  PipelineConfig c = testing::small_config(technique);
  set_config_field(c, "back_light", "0");
  set_config_field(c, "shadow_taps", "1");
  return c;
}

PipelineConfig with(PipelineConfig c, const std::string& key, const std::string& value) {
  set_config_field(c, key, value);
  return c;
}

struct Difference {
  double mean = 0.0;  // over the RGB channels of pixels lit in either frame
  double max = 0.0;
};

// The background is cleared to black: a pixel black in both frames is not drawn.
Difference difference(const sim::RenderTarget& a, const sim::RenderTarget& b) {
  Difference d;
  int n = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const glm::vec3 pa(a.pixels[i]), pb(b.pixels[i]);
    if (pa == glm::vec3(0.0f) && pb == glm::vec3(0.0f)) continue;
    const glm::vec3 e = glm::abs(pa - pb);
    d.mean += e.r + e.g + e.b;
    d.max = std::max<double>(d.max, std::max({e.r, e.g, e.b}));
    n += 3;
  }
  if (n > 0) d.mean /= n;
  return d;
}

bool all_finite(const sim::RenderTarget& frame) {
  return std::all_of(frame.pixels.begin(), frame.pixels.end(), [](const glm::vec4& p) {
    return std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b);
  });
}

struct Shader {
  const char* technique;
  const char* program;  // its ks_lut skin program
};

void PrintTo(const Shader& s, std::ostream* os) {
  *os << s.technique;
}

class SpecularKnob : public ::testing::TestWithParam<Shader> {};

TEST_P(SpecularKnob, AnalyticModelsTradeTheLutReadForAlu) {
  const Shader& s = GetParam();
  const FrameOutput lut = render(small_config(s.technique));
  const sim::DrawCounters& base = skin_draw(lut);
  EXPECT_EQ(base.fragment_program, s.program);
  EXPECT_EQ(base.fragment_profile.texture_reads_dependent, 1u);
  for (const char* spec : kAnalytic) {
    const FrameOutput out = render(with(small_config(s.technique), "specular", spec));
    const sim::DrawCounters& d = skin_draw(out);
    EXPECT_EQ(d.fragment_program, std::string(s.program) + "_" + spec);
    EXPECT_EQ(d.fragment_profile.texture_reads_dependent, 0u) << spec;
    EXPECT_EQ(d.fragment_profile.texture_reads_independent,
              base.fragment_profile.texture_reads_independent)
        << spec;
    EXPECT_GT(d.fragment_profile.alu_ops(), base.fragment_profile.alu_ops()) << spec;
    EXPECT_EQ(d.fragments_shaded, base.fragments_shaded) << spec;
    // The skin render samples the LUT no more (eyes and background are unchanged).
    EXPECT_EQ(lut.passes.back().texture.samples() - out.passes.back().texture.samples(),
              d.fragments_shaded)
        << spec;
  }
}

TEST_P(SpecularKnob, ImagesDifferPlausibly) {
  const Shader& s = GetParam();
  const FrameOutput lut = render(small_config(s.technique));
  const FrameOutput ks = render(with(small_config(s.technique), "specular", "ks"));
  for (const char* spec : kAnalytic) {
    const FrameOutput out = render(with(small_config(s.technique), "specular", spec));
    ASSERT_TRUE(all_finite(out.frame)) << spec;
    // Same diffuse light, another specular model: a few 8-bit levels on average, never a
    // different picture (the most is at grazing angles, where Schlick's F(N.V) scales the
    // environment rim light instead of the LUT's lobe-averaged Fresnel).
    const Difference d = difference(lut.frame, out.frame);
    EXPECT_GT(d.mean, 1.0 / 255.0 / 4.0) << spec;
    EXPECT_LT(d.mean, 0.01) << spec;
    EXPECT_LT(d.max, 0.25) << spec;
    const glm::vec3 face = centre_mean(out.frame);  // still skin: red above green above blue
    EXPECT_GT(face.r, face.g) << spec;
    EXPECT_GT(face.g, face.b) << spec;
    if (std::string(spec) != "ks") {
      EXPECT_GT(difference(ks.frame, out.frame).mean, 0.0) << spec << ": another lobe shape";
    }
  }
}

TEST_P(SpecularKnob, AnalyticModelsDifferOnlyInTheKeyLightLobe) {
  // The analytic models share Fresnel, the rim light and the diffuse energy term: without
  // the key light's specular (rho_s = 0) their frames are identical.
  const Shader& s = GetParam();
  const PipelineConfig no_lobe = with(small_config(s.technique), "specular_intensity", "0");
  const FrameOutput ks = render(with(no_lobe, "specular", "ks"));
  for (const char* spec : {"ggx", "dual_ggx"}) {
    EXPECT_EQ(render(with(no_lobe, "specular", spec)).frame.pixels, ks.frame.pixels) << spec;
  }
}

TEST_P(SpecularKnob, LutKnobsMatterOnlyToTheLutModel) {
  const Shader& s = GetParam();
  const auto frame = [&](const std::string& spec, const std::string& lut, const std::string& fmt) {
    return render(with(with(with(small_config(s.technique), "specular", spec), "lut", lut),
                       "lut_format", fmt));
  };
  const FrameOutput small_lut = frame("ks_lut", "8x32", "rgba8");
  EXPECT_NE(small_lut.frame.pixels, frame("ks_lut", "64x256", "rgba16f").frame.pixels);
  const FrameOutput a = frame("ggx", "8x32", "rgba8"), b = frame("ggx", "64x256", "rgba16f");
  EXPECT_EQ(a.frame.pixels, b.frame.pixels);
  EXPECT_EQ(a.passes.back().texture.samples(), b.passes.back().texture.samples());
  EXPECT_EQ(a.passes.back().texture.dram_bytes, b.passes.back().texture.dram_bytes);
}

INSTANTIATE_TEST_SUITE_P(Shaders, SpecularKnob,
                         ::testing::Values(Shader{"mobile", "skin_fs"},
                                           Shader{"lod", "skin_lod_fs"}, Shader{"wrap", "wrap_fs"}),
                         [](const ::testing::TestParamInfo<Shader>& p) {
                           return std::string(p.param.technique);
                         });

}  // namespace
}  // namespace skinsim::pipeline

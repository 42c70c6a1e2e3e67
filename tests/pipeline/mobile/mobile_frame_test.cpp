// The mobile pipeline's passes on the emulated GPU: structure, op profiles, scaling.
#include <gtest/gtest.h>

#include "pipeline/frame.h"
#include "pipeline/shader_catalog.h"
#include "tests/pipeline/mobile/test_scenes.h"

namespace skinsim::pipeline {
namespace {

const sim::PassCounters& pass(const FrameOutput& f, const std::string& name) {
  for (const sim::PassCounters& p : f.passes) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no pass " + name);
}

FrameOutput render(const GpuScene& gs, float scale, int blur_iterations = 1,
                   float blur_follow_mm = 0.0f) {
  PipelineConfig c;
  c.width = 512;
  c.height = 384;
  c.mobile.scale = scale;
  c.mobile.blur_iterations = blur_iterations;
  c.mobile.blur_follow_mm = blur_follow_mm;
  sim::Gpu gpu(sim::GpuConfig{});
  return render_frame(gs, c, gpu);
}

// With the default knobs on the built-in scene: albedo, normal map, environment, the shadow
// map's first tap and the blurred buffer; the shadow map's three other taps and the BRDF LUT
// once per light (key and back).
TEST(MobilePipeline, SkinShaderReadsFiveIndependentAndFiveDependentTextures) {
  bool found = false;
  for (const auto& [s, techniques] : shader_catalog()) {
    if (s.name != "skin_fs") continue;
    found = true;
    EXPECT_EQ(s.profile.texture_reads_independent, 5u);
    EXPECT_EQ(s.profile.texture_reads_dependent, 5u);
    EXPECT_GT(s.profile.alu_ops(), 20u);
  }
  EXPECT_TRUE(found);
}

TEST(MobilePipeline, PassesInOrderWithTheirTargets) {
  const scene::Scene s = testing::small_head();
  const GpuScene gs(s);
  const FrameOutput f = render(gs, 0.5f, 2);
  std::vector<std::string> names;
  for (const auto& p : f.passes) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"shadow", "irradiance", "blur_h", "blur_v", "blur_h2",
                                             "blur_v2", "skin"}));
  EXPECT_EQ(pass(f, "irradiance").width, 256);
  EXPECT_EQ(pass(f, "skin").width, 512);
  EXPECT_EQ(f.decisions.at("lod_shader"), 0.0);
  // Eyes are not in the irradiance buffer: only skin draws.
  for (const auto& d : pass(f, "irradiance").draws)
    EXPECT_EQ(d.fragment_program, "skin_irradiance_fs");
  // The blur touches only the skin's bounding rectangle, not every tile of the buffer.
  EXPECT_LE(pass(f, "blur_h").tiles_rendered, static_cast<std::uint64_t>(8 * 6));
  ASSERT_EQ(f.intermediates.size(), 3u);  // irradiance, blurred, shadow_map
}

// blur_follow_mm: the buffer's alpha carries depth and the blur's taps follow the surface:
// the same nine reads per pixel (nearest now), more ALU, and a different image where
// surfaces overlap; the skin pass is unchanged.
TEST(MobilePipeline, DepthAwareBlurAddsAluNotReads) {
  const scene::Scene s = testing::small_head();
  const GpuScene gs(s);
  const FrameOutput plain = render(gs, 0.5f), follow = render(gs, 0.5f, 2, 4.0f);
  const FrameOutput plain2 = render(gs, 0.5f, 2);
  for (const char* name : {"blur_h", "blur_v", "blur_h2", "blur_v2"}) {
    const sim::DrawCounters& a = pass(plain2, name).draws.at(0);
    const sim::DrawCounters& b = pass(follow, name).draws.at(0);
    EXPECT_EQ(b.fragment_program, "blur_follow_fs") << name;
    EXPECT_EQ(b.fragment_profile.texture_reads_independent, 9u) << name;
    EXPECT_GT(b.fragment_profile.alu_ops(), a.fragment_profile.alu_ops() + 30) << name;
    EXPECT_EQ(pass(follow, name).texture.samples_by_filter[0], pass(follow, name).texture.samples())
        << name << ": nearest taps";
  }
  EXPECT_EQ(pass(follow, "skin").draws.back().fragment_program,
            pass(plain, "skin").draws.back().fragment_program);
  EXPECT_NE(follow.frame.pixels, plain2.frame.pixels);
}

TEST(MobilePipeline, BufferScaleScalesIrradianceAndBlurWorkBySquare) {
  const scene::Scene s = testing::small_head();
  const GpuScene gs(s);
  const FrameOutput full = render(gs, 1.0f), half = render(gs, 0.5f);
  const double irr_ratio = static_cast<double>(pass(half, "irradiance").fragments_shaded) /
                           pass(full, "irradiance").fragments_shaded;
  EXPECT_NEAR(irr_ratio, 0.25, 0.02);
  const double blur_ratio = static_cast<double>(pass(half, "blur_h").fragments_shaded) /
                            pass(full, "blur_h").fragments_shaded;
  EXPECT_NEAR(blur_ratio, 0.25, 0.03);
  // The final pass does not depend on the buffer size.
  EXPECT_EQ(pass(half, "skin").fragments_shaded, pass(full, "skin").fragments_shaded);
}

TEST(MobilePipeline, LodTechniqueIsOneSkinPass) {
  const scene::Scene s = testing::small_head();
  const GpuScene gs(s);
  PipelineConfig c;
  c.width = 256;
  c.height = 192;
  c.technique = "lod";
  sim::Gpu gpu(sim::GpuConfig{});
  const FrameOutput f = render_frame(gs, c, gpu);
  ASSERT_EQ(f.passes.size(), 2u);
  EXPECT_EQ(f.passes[0].name, "shadow");
  EXPECT_EQ(f.passes[1].name, "skin");
  EXPECT_EQ(f.decisions.at("lod_shader"), 1.0);
}

TEST(MobilePipeline, IdenticalForAnyThreadCount) {
  const scene::Scene s = testing::small_head();
  const GpuScene gs(s);
  PipelineConfig c;
  c.width = 320;
  c.height = 240;
  sim::GpuConfig one, two;
  one.threads = 1;
  two.threads = 2;
  sim::Gpu g1(one), g2(two);
  const FrameOutput a = render_frame(gs, c, g1), b = render_frame(gs, c, g2);
  EXPECT_EQ(a.frame.pixels, b.frame.pixels);
  ASSERT_EQ(a.passes.size(), b.passes.size());
  for (size_t i = 0; i < a.passes.size(); ++i) {
    EXPECT_EQ(a.passes[i].fragments_shaded, b.passes[i].fragments_shaded);
    EXPECT_EQ(a.passes[i].texture.cache_misses, b.passes[i].texture.cache_misses);
  }
}

}  // namespace
}  // namespace skinsim::pipeline

// Where no approximation matters (a flat, uniformly lit patch), the pipeline and the
// reference agree; on a real head they differ, and by less for a larger LUT.
#include <gtest/gtest.h>

#include "driver/frame/frame_quality.h"
#include "driver/frame/images.h"
#include "pipeline/frame.h"
#include "pipeline/reference/reference.h"
#include "scene/procedural_head.h"
#include "tests/pipeline/mobile/test_scenes.h"

namespace skinsim::pipeline {
namespace {

class FlatPatch : public ::testing::TestWithParam<ReferenceProfile> {};

// Either profile is normalised over skin: uniform light stays uniform.
TEST_P(FlatPatch, MatchesThePipeline) {
  const scene::Scene s = testing::flat_skin_patch(0.6f, 0.05f);
  const GpuScene gs(s);
  PipelineConfig c;
  c.reference_profile = GetParam();
  c.width = 128;
  c.height = 96;
  c.gamma = GammaMode::kSrgb;  // the reference encodes exact sRGB
  c.lut_format = sim::TexelFormat::kRGBA16F;
  sim::Gpu gpu(sim::GpuConfig{});
  const FrameOutput f = render_frame(gs, c, gpu);
  const ReferenceFrame ref = render_reference(gs, c, 0);
  int compared = 0;
  for (int y = 8; y < c.height - 8; ++y) {
    for (int x = 8; x < c.width - 8; ++x) {
      if (!ref.skin_mask[static_cast<size_t>(y) * c.width + x]) continue;
      const glm::vec3 a(f.frame.at(x, y)), b(ref.frame.at(x, y));
      ASSERT_NEAR(a.r, b.r, 3.0f / 255) << x << "," << y;
      ASSERT_NEAR(a.g, b.g, 3.0f / 255) << x << "," << y;
      ASSERT_NEAR(a.b, b.b, 3.0f / 255) << x << "," << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 1000);
}

INSTANTIATE_TEST_SUITE_P(ReferenceAgreement, FlatPatch,
                         ::testing::Values(ReferenceProfile::kSixGaussian,
                                           ReferenceProfile::kDipole),
                         [](const ::testing::TestParamInfo<ReferenceProfile>& p) {
                           return std::string(reference_profile_name(p.param));
                         });

TEST(ReferenceAgreement, HeadQualityIsWhereItWasMeasured) {
  const scene::Scene s = testing::small_head();
  const GpuScene gs(s);
  PipelineConfig c;
  c.width = 256;
  c.height = 192;
  sim::Gpu gpu(sim::GpuConfig{});
  const FrameOutput f = render_frame(gs, c, gpu);
  const driver::ReferenceImages ref = driver::reference_images(render_reference(gs, c, 0));
  const driver::FrameQuality q = driver::evaluate_quality(driver::to_image(f.frame), ref);
  // Measured: SSIM 0.9870 and FLIP 0.0755 over the skin (0.9887 and 0.0792 while the
  // reference's ambient reached every skin point unoccluded, ambient_visibility.h; 0.9759 and
  // 0.0808 while its shadow rays left the flat facets, which shadowed this coarse head's own
  // terminator: shadow_origin.h). The margins (0.005, 10% of FLIP) let the frame move a
  // little; a change that moves it more updates these, saying why.
  EXPECT_NEAR(q.metrics.at("ssim_skin"), 0.9870, 0.005);
  EXPECT_NEAR(q.metrics.at("flip_skin"), 0.0755, 0.0075);
}

// The dipole technique is judged closer to the ground truth with its own profile (Jensen's
// Skin1 dipole) than to the six Gaussians: the choice of reference moves the score.
TEST(ReferenceAgreement, DipoleTechniqueIsCloserToTheDipoleReference) {
  // The default head: on the small head's coarse facets the two references differ less.
  const scene::Scene s = scene::make_default_scene({});
  const GpuScene gs(s);
  PipelineConfig c;
  c.technique = "dipole";
  c.width = 256;
  c.height = 192;
  sim::Gpu gpu(sim::GpuConfig{});
  const FrameOutput f = render_frame(gs, c, gpu);
  const auto flip = [&](ReferenceProfile profile) {
    c.reference_profile = profile;
    const driver::ReferenceImages ref = driver::reference_images(render_reference(gs, c, 0));
    return driver::evaluate_quality(driver::to_image(f.frame), ref).metrics.at("flip_skin");
  };
  EXPECT_LT(flip(ReferenceProfile::kDipole), flip(ReferenceProfile::kSixGaussian));
}

}  // namespace
}  // namespace skinsim::pipeline

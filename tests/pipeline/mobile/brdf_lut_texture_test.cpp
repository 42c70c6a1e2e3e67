// The BRDF LUT texture: one bake per distinct LUT, shared by the frames that use it.
#include "pipeline/brdf_lut_texture.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace skinsim::pipeline {
namespace {

TEST(BrdfLutTexture, SharedBakesOncePerDistinctLut) {
  PipelineConfig c;
  c.lut_width = 8;
  c.lut_height = 32;
  const auto first = BrdfLutTexture::shared(c);
  EXPECT_EQ(BrdfLutTexture::shared(c), first);

  PipelineConfig other_size = c;
  other_size.lut_width = 16;
  EXPECT_NE(BrdfLutTexture::shared(other_size), first);
  PipelineConfig other_format = c;
  other_format.lut_format = sim::TexelFormat::kRGBA16F;
  EXPECT_NE(BrdfLutTexture::shared(other_format), first);
  PipelineConfig other_intensity = c;
  other_intensity.specular_intensity = 0.3f;
  EXPECT_NE(BrdfLutTexture::shared(other_intensity), first);
}

TEST(BrdfLutTexture, SharedMatchesAFreshBake) {
  PipelineConfig c;
  c.lut_width = 8;
  c.lut_height = 32;
  c.specular_intensity = 0.25f;
  const sim::Texture2D& shared = BrdfLutTexture::shared(c)->texture();
  const BrdfLutTexture fresh = BrdfLutTexture::bake(c);
  ASSERT_EQ(shared.level_count(), fresh.texture().level_count());
  for (int l = 0; l < shared.level_count(); ++l) {
    const sim::LevelView& a = shared.level(l);
    const sim::LevelView& b = fresh.texture().level(l);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    EXPECT_TRUE(
        std::equal(a.texels, a.texels + static_cast<std::size_t>(a.width) * a.height, b.texels))
        << "level " << l;
  }
}

}  // namespace
}  // namespace skinsim::pipeline

// The blur's alpha mask keeps light from leaking between skin and background.
#include <gtest/gtest.h>

#include "pipeline/blur_pass.h"

namespace skinsim::pipeline {
namespace {

// The buffer is premultiplied: background (no skin) is cleared to 0, and a blur that
// normalised naively would darken the skin at the border or spread skin light outward.
TEST(BlurMask, SkinNextToBackgroundStaysUnchangedAtTheBorder) {
  const int w = 96, h = 64;
  sim::RenderTarget buffer("irradiance", w, h, sim::TexelFormat::kRGBA8);
  const glm::vec4 skin(0.2f, 0.3f, 0.4f, 1.0f), background(0.0f);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x)
      buffer.at(x, y) = sim::quantize(x < w / 2 ? skin : background, buffer.format);
  }
  sim::RenderTarget out("blurred", w, h, sim::TexelFormat::kRGBA8);
  sim::Gpu gpu(sim::GpuConfig{});
  const sim::PixelRect all{0, 0, w, h};
  blur_pass("blur_h", buffer, out, all, {1, 0}, 6.0f, gpu);
  const glm::vec4 expected = sim::quantize(skin, out.format);
  for (int y = 0; y < h; ++y) {
    for (int x = w / 2 - 8; x < w / 2; ++x) {
      ASSERT_NEAR(out.at(x, y).r, expected.r, 1.0f / 255) << x << "," << y;
      ASSERT_NEAR(out.at(x, y).b, expected.b, 1.0f / 255) << x << "," << y;
    }
    for (int x = w / 2; x < w; ++x) ASSERT_EQ(out.at(x, y), glm::vec4(0.0f)) << x;
  }
}

TEST(BlurMask, BlurSpreadsLightWithinSkin) {
  const int w = 64, h = 32;
  sim::RenderTarget buffer("irradiance", w, h, sim::TexelFormat::kRGBA8);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) buffer.at(x, y) = glm::vec4(x < w / 2 ? 0.0f : 1.0f, 0, 0, 1);
  }
  sim::RenderTarget out("blurred", w, h, sim::TexelFormat::kRGBA8);
  sim::Gpu gpu(sim::GpuConfig{});
  blur_pass("blur_h", buffer, out, {0, 0, w, h}, {1, 0}, 4.0f, gpu);
  EXPECT_GT(out.at(w / 2 - 2, 5).r, 0.05f);  // light crossed the edge inside the skin
  EXPECT_LT(out.at(w / 2 + 1, 5).r, 0.95f);
  EXPECT_NEAR(out.at(2, 5).r, 0.0f, 1e-6f);
}

}  // namespace
}  // namespace skinsim::pipeline

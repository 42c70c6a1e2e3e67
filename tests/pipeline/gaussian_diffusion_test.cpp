#include "pipeline/reference/gaussian_diffusion.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "util/simd_dispatch.h"

namespace skinsim::pipeline {
namespace {

constexpr float kSkin = 1.0f;
constexpr float kOther = 0.0f;

// A bumpy sheet of skin seen orthographically at 4 pixels per mm (1 unit = 1 mm), with a
// round hole of another material: the widest Gaussian's grid (+-3 sigma, 33 pixels) fits
// inside the image for the pixels in its middle and reaches beyond the borders elsewhere,
// and every Gaussian but the narrowest uses a grid of taps.
struct Sheet {
  static constexpr int kWidth = 160, kHeight = 128;
  sim::RenderTarget position{"position", kWidth, kHeight, sim::TexelFormat::kRGBA32F};
  std::vector<glm::vec3> irradiance;
  View view;

  explicit Sheet(bool uniform_light) {
    view.orthographic = true;
    view.focal_pixels = 4.0f;
    view.width = kWidth;
    view.height = kHeight;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const float u = static_cast<float>(x) / 4.0f, v = static_cast<float>(y) / 4.0f;
        const bool hole = (x - 100) * (x - 100) + (y - 60) * (y - 60) < 64;
        position.at(x, y) =
            glm::vec4(u, v, 0.5f * std::sin(0.3f * u) * std::cos(0.2f * v), hole ? kOther : kSkin);
        irradiance.push_back(uniform_light
                                 ? glm::vec3(0.25f, 0.5f, 0.75f)
                                 : glm::vec3(0.5f + 0.5f * std::sin(0.7f * u),
                                             (x * 7 + y * 13) % 11 / 10.0f, x < 80 ? 1.0f : 0.1f));
      }
    }
  }

  std::vector<glm::vec3> diffused() const {
    const GaussianDiffusion diffusion(position, kSkin, irradiance, view, 1.0f);
    std::vector<glm::vec3> out(static_cast<std::size_t>(kWidth) * kHeight, glm::vec3(-1.0f));
    for (int y = 0; y < kHeight; ++y) {
      // Rows split unevenly, as the reference's blocks split them.
      diffusion.row(y, 0, 37, &out[static_cast<std::size_t>(y) * kWidth]);
      diffusion.row(y, 37, kWidth, &out[static_cast<std::size_t>(y) * kWidth + 37]);
    }
    return out;
  }
};

TEST(GaussianDiffusion, UniformLightStaysUniformAndOtherPixelsAreLeftAlone) {
  const Sheet sheet(true);
  const std::vector<glm::vec3> m = sheet.diffused();
  for (int y = 0; y < Sheet::kHeight; ++y) {
    for (int x = 0; x < Sheet::kWidth; ++x) {
      const glm::vec3 v = m[static_cast<std::size_t>(y) * Sheet::kWidth + x];
      if (sheet.position.at(x, y).w != kSkin) {
        EXPECT_EQ(v, glm::vec3(-1.0f)) << x << "," << y;
        continue;
      }
      // The profile's weights sum to 1, and each Gaussian is normalised over its taps.
      EXPECT_NEAR(v.r, 0.25f, 1e-5f) << x << "," << y;
      EXPECT_NEAR(v.g, 0.5f, 1e-5f) << x << "," << y;
      EXPECT_NEAR(v.b, 0.75f, 1e-5f) << x << "," << y;
    }
  }
}

// Two pixels share eight AVX lanes where the processor has AVX; the SSE2 baseline takes one
// pixel's four widest Gaussians at a time. Both must give the same bits.
TEST(GaussianDiffusion, AvxAndBaselineGiveTheSameBits) {
  if (!__builtin_cpu_supports("avx")) GTEST_SKIP() << "this processor has no AVX";
  const Sheet sheet(false);
  ASSERT_TRUE(use_avx());
  const std::vector<glm::vec3> avx = sheet.diffused();
  std::vector<glm::vec3> baseline;
  {
    const BaselineSimdScope scope;
    baseline = sheet.diffused();
  }
  ASSERT_EQ(avx.size(), baseline.size());
  int differing = 0;
  for (std::size_t i = 0; i < avx.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (std::bit_cast<std::uint32_t>(avx[i][c]) != std::bit_cast<std::uint32_t>(baseline[i][c])) {
        ++differing;
      }
    }
  }
  EXPECT_EQ(differing, 0);
  // The light varies, so diffusion changed it: the comparison is not of two copies of the input.
  EXPECT_NE(avx[static_cast<std::size_t>(64) * Sheet::kWidth + 80],
            sheet.irradiance[64 * Sheet::kWidth + 80]);
}

}  // namespace
}  // namespace skinsim::pipeline

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstring>

#include "pipeline/bake/error.h"
#include "pipeline/bake/preintegrated_lut.h"

namespace skinsim::bake {
namespace {

TEST(Preintegrated, FlatSkinIsLambert) {
  for (float n_dot_l = -1.0f; n_dot_l <= 1.0f; n_dot_l += 0.125f) {
    const glm::vec3 d = preintegrated_diffuse(n_dot_l, 1e4f);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(d[c], std::max(0.0f, n_dot_l), 1e-3f) << "N.L = " << n_dot_l << " c " << c;
    }
  }
}

TEST(Preintegrated, CurvedSkinWrapsRedLightPastTheTerminator) {
  const glm::vec3 at_terminator = preintegrated_diffuse(0.0f, 2.0f);
  EXPECT_GT(at_terminator.r, at_terminator.g);
  EXPECT_GT(at_terminator.g, at_terminator.b);
  EXPECT_GT(at_terminator.b, 0.0f);
  // Light that wraps into the shadow is taken from the lit side.
  const glm::vec3 facing = preintegrated_diffuse(1.0f, 2.0f);
  EXPECT_LT(facing.r, 1.0f);
  EXPECT_LT(facing.r, facing.b);
}

TEST(Preintegrated, LutRowsAreMonotoneInNdotL) {
  PreintegratedLutParams p;
  p.width = 64;
  p.height = 32;
  const PreintegratedLut lut = bake_preintegrated_lut(p);
  ASSERT_EQ(lut.rgb.size(), 64u * 32u);
  for (int y = 0; y < lut.height; ++y) {
    for (int x = 1; x < lut.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_GE(lut.at(x, y)[c], lut.at(x - 1, y)[c] - 1e-6f) << x << "," << y << " c " << c;
        ASSERT_LE(lut.at(x, y)[c], 1.0f + 1e-6f);
      }
    }
  }
  // Row 0 is nearly flat skin: saturate(N.L).
  for (int x = 0; x < lut.width; ++x) {
    const float n_dot_l = 2.0f * (x + 0.5f) / lut.width - 1.0f;
    EXPECT_NEAR(lut.at(x, 0).g, std::max(0.0f, n_dot_l), 2e-3f);
  }
}

TEST(Preintegrated, SameBitsForAnyThreadCount) {
  PreintegratedLutParams p;
  p.width = 32;
  p.height = 48;
  PreintegratedLut single;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    single = bake_preintegrated_lut(p);
  }
  const PreintegratedLut parallel = bake_preintegrated_lut(p);
  ASSERT_EQ(single.rgb.size(), parallel.rgb.size());
  EXPECT_EQ(
      std::memcmp(single.rgb.data(), parallel.rgb.data(), single.rgb.size() * sizeof(glm::vec3)),
      0);
}

TEST(Preintegrated, BadParametersNameTheField) {
  PreintegratedLutParams p;
  p.max_curvature_per_mm = 0.0f;
  try {
    bake_preintegrated_lut(p);
    FAIL() << "zero curvature range accepted";
  } catch (const BakeError& e) {
    EXPECT_NE(std::string(e.what()).find("max_curvature_per_mm"), std::string::npos) << e.what();
  }
  EXPECT_THROW(preintegrated_diffuse(0.5f, 0.0f), BakeError);
}

}  // namespace
}  // namespace skinsim::bake

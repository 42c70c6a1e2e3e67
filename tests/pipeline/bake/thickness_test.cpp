// The offline bakes behind shadows and transmission: the per-vertex thickness (rays cast with
// Embree) and Penner's penumbra-scattering LUT.
#include "pipeline/bake/thickness.h"

#include <gtest/gtest.h>

#include "pipeline/bake/ray_scene.h"
#include "pipeline/bake/shadow_scatter_lut.h"

namespace skinsim::bake {
namespace {

// Two 100 x 100 mm squares 3 mm apart (units: mm), like the two faces of an ear.
struct Slab {
  std::vector<glm::vec3> positions{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0},
                                   {-50, -50, 3}, {50, -50, 3}, {50, 50, 3}, {-50, 50, 3}};
  std::vector<std::uint32_t> indices{0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7};
};

TEST(Thickness, IsTheDistanceThroughThePart) {
  const Slab slab;
  const RayScene rays({{&slab.positions, &slab.indices}});
  // The front face's normal points away from the back face (+z from z = 3).
  const std::vector<glm::vec3> points{{0, 0, 3}, {10, -5, 0}};
  const std::vector<glm::vec3> normals{{0, 0, 1}, {0, 0, -1}};
  const std::vector<float> t = bake_thickness_mm(rays, points, normals, 1.0f);
  // The cone's rays run up to 30 degrees off the normal: 3 mm to 3 / cos 30 = 3.46 mm.
  for (const float mm : t) {
    EXPECT_GT(mm, 3.0f);
    EXPECT_LT(mm, 3.3f);
  }
  // Facing out of the slab's edge region into nothing: as thick as the bake's maximum.
  EXPECT_EQ(thickness_at_mm(rays, {0, 0, 3}, {0, 0, -1}, 1.0f), kMaxThicknessMm);
}

TEST(ShadowScatterLut, KeepsFullLightAndShadowAndReddensThePenumbra) {
  const std::vector<glm::vec3> lut = shadow_scatter_lut(32, 2.0f);
  EXPECT_EQ(lut.front(), glm::vec3(0.0f));
  EXPECT_EQ(lut.back(), glm::vec3(1.0f));
  for (std::size_t i = 1; i < lut.size(); ++i) {
    EXPECT_GE(lut[i].r, lut[i - 1].r);  // monotonic
    EXPECT_GE(lut[i].b, lut[i - 1].b);
  }
  // On the shadowed side of the penumbra red scatters in furthest.
  const glm::vec3 dark = lut[8];
  EXPECT_GT(dark.r, dark.g);
  EXPECT_GT(dark.g, dark.b);
}

}  // namespace
}  // namespace skinsim::bake

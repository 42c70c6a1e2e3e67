// The urp technique's offline bakes: the per-vertex ambient occlusion (rays cast with Embree)
// and the generated pore normal map.
#include <gtest/gtest.h>

#include "pipeline/bake/ambient_occlusion.h"
#include "pipeline/bake/pore_normals.h"
#include "pipeline/bake/ray_scene.h"

namespace skinsim::bake {
namespace {

// A 100 x 100 mm floor (units: mm) and a 100 mm wall standing on its edge at x = 50.
struct Corner {
  std::vector<glm::vec3> positions{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0},   {-50, 50, 0},
                                   {50, -50, 0},  {50, 50, 0},  {50, 50, 100}, {50, -50, 100}};
  std::vector<std::uint32_t> indices{0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7};
};

TEST(BakedAo, IsOneInTheOpenAndLessInACorner) {
  const Corner corner;
  const RayScene rays({{&corner.positions, &corner.indices}});
  const glm::vec3 up(0, 0, 1);
  // Far from the wall (beyond the bake's reach): open.
  EXPECT_EQ(ambient_occlusion_at(rays, {-45, 0, 0}, up, 1.0f), 1.0f);
  // At the wall's foot half the hemisphere's cosine-weighted light is blocked.
  const float foot = ambient_occlusion_at(rays, {49, 0, 0}, up, 1.0f);
  EXPECT_GT(foot, 0.3f);
  EXPECT_LT(foot, 0.7f);
  // Nearer the wall, darker.
  EXPECT_LT(foot, ambient_occlusion_at(rays, {30, 0, 0}, up, 1.0f));
}

TEST(PoreNormals, AreDeterministicUnitAndTile) {
  const PoreNormalParams params;
  const std::vector<glm::vec3> a = bake_pore_normals(params);
  EXPECT_EQ(a, bake_pore_normals(params));
  ASSERT_EQ(a.size(), static_cast<std::size_t>(params.size * params.size));
  float tilt = 0.0f;
  for (const glm::vec3& n : a) {
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_GT(n.z, 0.0f);
    tilt = std::max(tilt, 1.0f - n.z);
  }
  EXPECT_GT(tilt, 0.05f);  // the pores tilt the normal
}

}  // namespace
}  // namespace skinsim::bake

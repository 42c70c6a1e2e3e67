// The offline bakes behind shadows and transmission: the per-vertex thickness (rays cast with
// Embree) and Penner's penumbra-scattering LUT.
#include "pipeline/bake/thickness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

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

// Rays traced as packets (unoccluded) answer as one at a time (occluded): over a bumpy
// surface, from points just above it, in directions from grazing to steep, in packets that
// are full, partial and more than one.
TEST(RayScene, PacketsAnswerAsSingleRays) {
  constexpr int kGrid = 48;
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  for (int j = 0; j <= kGrid; ++j) {
    for (int i = 0; i <= kGrid; ++i) {
      const float x = static_cast<float>(i), y = static_cast<float>(j);
      positions.emplace_back(x, y, 2.0f * std::sin(0.7f * x) * std::cos(0.45f * y));
    }
  }
  for (int j = 0; j < kGrid; ++j) {
    for (int i = 0; i < kGrid; ++i) {
      const std::uint32_t a = j * (kGrid + 1) + i, b = a + 1, c = a + kGrid + 1, d = c + 1;
      indices.insert(indices.end(), {a, b, d, a, d, c});
    }
  }
  const RayScene rays({{&positions, &indices}});
  int blocked = 0, open = 0;
  for (int p = 0; p < 60; ++p) {
    const float x = 4.0f + 0.67f * static_cast<float>(p), y = 5.0f + 0.61f * static_cast<float>(p);
    const glm::vec3 origin(x, y, 2.0f * std::sin(0.7f * x) * std::cos(0.45f * y) + 0.05f);
    for (const int count : {1, 16, 17, 40}) {
      std::vector<glm::vec3> directions;
      for (int k = 0; k < count; ++k) {
        const float azimuth = 0.83f * static_cast<float>(k + p);
        const float elevation = 0.02f + 1.2f * static_cast<float>(k) / static_cast<float>(count);
        directions.push_back(glm::normalize(glm::vec3(std::cos(azimuth) * std::cos(elevation),
                                                      std::sin(azimuth) * std::cos(elevation),
                                                      std::sin(elevation))));
      }
      for (const float reach : {3.0f, std::numeric_limits<float>::infinity()}) {
        int single = 0;
        for (const glm::vec3& d : directions)
          single += rays.occluded(origin, d, 0.01f, reach) ? 0 : 1;
        ASSERT_EQ(rays.unoccluded(origin, directions, 0.01f, reach), single)
            << "point " << p << ", " << count << " rays, reach " << reach;
        // Each ray's own answer, as the reference's ambient rays read them.
        const auto each = std::make_unique<bool[]>(directions.size());
        rays.unoccluded(origin, directions, 0.01f, reach, {each.get(), directions.size()});
        for (std::size_t k = 0; k < directions.size(); ++k) {
          ASSERT_EQ(each[k], !rays.occluded(origin, directions[k], 0.01f, reach))
              << "point " << p << ", ray " << k << " of " << count << ", reach " << reach;
        }
        open += single;
        blocked += count - single;
      }
    }
  }
  // Both answers occur often, or the comparison would prove little.
  EXPECT_GT(blocked, 1000);
  EXPECT_GT(open, 1000);
  EXPECT_EQ(rays.unoccluded({0, 0, 10}, {}, 0.0f), 0);
}

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

#include "scene/studio_lighting.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/error.h"

namespace skinsim::scene {
namespace {

TEST(CubeFaceDirection, FaceCentresAndOrientationFollowOpenGL) {
  const glm::vec3 centres[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (int f = 0; f < 6; ++f) EXPECT_EQ(cube_face_direction(f, 0, 0), centres[f]) << f;
  // GL table 8.19: on +X, s = -z / |x|, t = -y / |x|; on +Z, s = x, t = -y.
  EXPECT_EQ(cube_face_direction(0, 0.5f, 0.25f), glm::vec3(1, -0.25f, -0.5f));
  EXPECT_EQ(cube_face_direction(4, 0.5f, 0.25f), glm::vec3(0.5f, -0.25f, 1));
  EXPECT_EQ(cube_face_direction(2, 0.5f, 0.25f), glm::vec3(0.5f, 1, 0.25f));
}

TEST(StudioEnvironment, BrightestTowardsTheKeyLightAndHdr) {
  const DirectionalLight key = default_key_light();
  const CubeMap env = make_studio_environment(32, key);
  ASSERT_EQ(env.size, 32);
  float best = 0.0f, best_dot = -2.0f, darkest = 1e9f;
  for (int f = 0; f < 6; ++f) {
    ASSERT_EQ(env.faces[f].size(), 32u * 32u);
    for (int y = 0; y < 32; ++y) {
      for (int x = 0; x < 32; ++x) {
        const glm::vec4 t = env.faces[f][y * 32 + x];
        const float lum = t.r + t.g + t.b;
        ASSERT_GE(t.r, 0.0f);
        darkest = std::min(darkest, lum);
        if (lum > best) {
          best = lum;
          best_dot = glm::dot(glm::normalize(cube_face_direction(f, 2 * (x + 0.5f) / 32 - 1,
                                                                 2 * (y + 0.5f) / 32 - 1)),
                              key.direction);
        }
      }
    }
  }
  EXPECT_GT(best / 3.0f, 1.0f);  // HDR: the softbox is brighter than white
  EXPECT_GT(best_dot, 0.9f);     // ... and sits around the key light
  EXPECT_GT(darkest, 0.0f);
}

// Pinned radiances, worked out by hand from the room's description: on an odd face size the
// centre texel looks straight along the face's axis. Up is the ceiling, down the floor and
// sideways (+X, -X) the horizon, each away from both softboxes (the key box is 1.5 of its
// tangent units from straight up, the rim box 1.8 from +X); the texel nearest the key light
// is inside the key box, whose radiance is added to the walls'.
TEST(StudioEnvironment, WallsAndKeyBoxHaveTheirStatedRadiance) {
  constexpr int kSize = 9;
  const DirectionalLight key = default_key_light();
  const CubeMap env = make_studio_environment(kSize, key);
  const auto centre = [&](int face) { return glm::vec3(env.faces[face][4 * kSize + 4]); };
  const glm::vec3 ceiling(0.32f, 0.31f, 0.30f), horizon(0.18f, 0.17f, 0.16f);
  EXPECT_EQ(centre(0), horizon);
  EXPECT_EQ(centre(1), horizon);
  EXPECT_EQ(centre(2), ceiling);
  EXPECT_EQ(centre(3), glm::vec3(0.05f, 0.045f, 0.04f));

  // The key light points into the +Z face; its nearest texel there.
  float best = -2.0f;
  glm::vec3 dir(0.0f), radiance(0.0f);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 d = glm::normalize(
          cube_face_direction(4, 2 * (x + 0.5f) / kSize - 1, 2 * (y + 0.5f) / kSize - 1));
      if (glm::dot(d, key.direction) <= best) continue;
      best = glm::dot(d, key.direction);
      dir = d;
      radiance = glm::vec3(env.faces[4][y * kSize + x]);
    }
  }
  ASSERT_GT(dir.y, 0.0f);
  const glm::vec3 wall = horizon + (ceiling - horizon) * std::sqrt(dir.y);
  const glm::vec3 key_box = radiance - wall;
  EXPECT_NEAR(key_box.r, 6.0f, 1e-5f);
  EXPECT_NEAR(key_box.g, 5.8f, 1e-5f);
  EXPECT_NEAR(key_box.b, 5.5f, 1e-5f);

  EXPECT_THROW(make_studio_environment(0, default_key_light()), SceneError);
  EXPECT_THROW(make_studio_environment(4097, default_key_light()), SceneError);
}

}  // namespace
}  // namespace skinsim::scene

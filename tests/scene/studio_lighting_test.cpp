#include "scene/studio_lighting.h"

#include <gtest/gtest.h>

#include <algorithm>

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

TEST(StudioEnvironment, DeterministicAndValidated) {
  const auto a = make_studio_environment(8, default_key_light());
  const auto b = make_studio_environment(8, default_key_light());
  for (int f = 0; f < 6; ++f) EXPECT_EQ(a.faces[f], b.faces[f]);
  EXPECT_THROW(make_studio_environment(0, default_key_light()), SceneError);
}

}  // namespace
}  // namespace skinsim::scene

#include "driver/sweep/crop_landmarks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skinsim::driver {
namespace {

// A 200x200 face: a skin disc of radius 80 at (100, 100) on grey, lit from the left (bright
// left of x = 70, dark right of it), with a hole (an eye) at (70, 70) and a red patch (lips)
// at (100, 150).
struct Face {
  image::Image image = image::Image::filled(200, 200, glm::vec3(0.4f));
  image::Mask skin = image::Mask::filled(200, 200, 0);
  Face() {
    for (int y = 0; y < 200; ++y) {
      for (int x = 0; x < 200; ++x) {
        const bool in_disc = std::hypot(x - 100, y - 100) < 80;
        const bool in_eye = std::hypot(x - 70, y - 70) < 8;
        if (!in_disc || in_eye) continue;
        skin.values[static_cast<std::size_t>(y) * 200 + x] = 1;
        const float light = x < 130 ? 0.8f : 0.3f;
        const bool lips = std::abs(x - 100) < 10 && std::abs(y - 150) < 4;
        image.at(x, y) =
            lips ? glm::vec3(0.8f, 0.3f, 0.3f) : glm::vec3(light, 0.7f * light, 0.6f * light);
      }
    }
  }
};

TEST(CropLandmarks, FindsTheEyeLipsShadowEdgeAndSilhouetteOfASyntheticFace) {
  const Face face;
  const std::vector<Landmark> found = find_landmarks(face.image, face.skin);
  ASSERT_EQ(found.size(), 4u);
  EXPECT_NE(found[0].why.find("eye"), std::string::npos);
  EXPECT_NEAR(found[0].x, 70, 1);
  EXPECT_NEAR(found[0].y, 70, 1);
  EXPECT_NE(found[1].why.find("lips"), std::string::npos);
  EXPECT_NEAR(found[1].x, 100, 10);
  EXPECT_NEAR(found[1].y, 150, 4);
  EXPECT_NE(found[2].why.find("shadow edge"), std::string::npos);
  EXPECT_NEAR(found[2].x, 130, 3);
  EXPECT_NE(found[3].why.find("silhouette"), std::string::npos);
  EXPECT_NEAR(found[3].x, 21, 1);  // the disc's left edge at y = 100
  EXPECT_EQ(found[3].y, 100);
}

TEST(CropLandmarks, NoSkinNoLandmarksAndNoHoleNoEye) {
  Face face;
  EXPECT_TRUE(find_landmarks(face.image, image::Mask::filled(200, 200, 0)).empty());
  for (int y = 60; y < 80; ++y) {  // fill the eye
    for (int x = 60; x < 80; ++x) {
      if (std::hypot(x - 70, y - 70) < 8)
        face.skin.values[static_cast<std::size_t>(y) * 200 + x] = 1;
    }
  }
  const std::vector<Landmark> found = find_landmarks(face.image, face.skin);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].why.find("eye"), std::string::npos);
}

// Skin of one flat colour (an untextured scan), lit and shadowed: the reddest spot in the
// lower middle is no redder than the rest, so there are no lips, and the search says so.
TEST(CropLandmarks, FlatColouredSkinHasNoLipsAndSaysSo) {
  Face face;
  for (int y = 140; y < 160; ++y) {
    for (int x = 85; x < 115; ++x) {
      const float light = x < 130 ? 0.8f : 0.3f;
      if (face.skin.values[static_cast<std::size_t>(y) * 200 + x])
        face.image.at(x, y) = glm::vec3(light, 0.7f * light, 0.6f * light);
    }
  }
  std::vector<std::string> not_found;
  const std::vector<Landmark> found = find_landmarks(face.image, face.skin, &not_found);
  ASSERT_EQ(found.size(), 3u);
  for (const Landmark& l : found) EXPECT_EQ(l.why.find("lips"), std::string::npos) << l.why;
  ASSERT_EQ(not_found.size(), 1u);
  EXPECT_NE(not_found[0].find("the lips: not found"), std::string::npos) << not_found[0];

  // With the red patch they are found and nothing is missing.
  EXPECT_EQ(find_landmarks(Face().image, Face().skin, &not_found).size(), 4u);
  EXPECT_TRUE(not_found.empty());
}

}  // namespace
}  // namespace skinsim::driver

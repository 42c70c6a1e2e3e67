// The noise floor's rule (driver/truth/truth_judge.h): a difference no larger than what the truth's
// second seed shows nearby is never called visible; without a second seed only the threshold
// applies. Hand-made images, no Blender.
#include <gtest/gtest.h>

#include "driver/truth/truth_judge.h"

namespace skinsim::driver {
namespace {

// A 40x40 grey image with white dots on a 5-pixel grid, offset by `at` in x and y.
image::Image dotted(int at) {
  image::Image image = image::Image::filled(40, 40, glm::vec3(0.5f));
  for (int y = at; y < 40; y += 5) {
    for (int x = at; x < 40; x += 5) image.rgb[static_cast<std::size_t>(y) * 40 + x] = glm::vec3(1);
  }
  return image;
}

TEST(TruthFloor, ADifferenceAsLargeAsTheSeedsNearbyIsNotVisible) {
  const image::Image grey = image::Image::filled(40, 40, glm::vec3(0.5f));
  // The second seed's draws are dots at (0,0) of each 5x5 block, the frame's at (2,2): the
  // same errors, at pixels where the second seed happened to agree with the truth.
  const Truth with_floor = with_images(Truth{}, TruthImages{grey, dotted(0)});
  const nlohmann::json judged = judge_against_truth(dotted(2), with_floor, nullptr);
  EXPECT_FALSE(judged["all"]["visible"].get<bool>()) << judged;
  EXPECT_EQ(judged["all"]["visible_px"], 0) << judged;

  const Truth one_image = with_images(Truth{}, TruthImages{grey, std::nullopt});
  const nlohmann::json alone = judge_against_truth(dotted(2), one_image, nullptr);
  EXPECT_TRUE(alone["all"]["visible"].get<bool>()) << alone;
}

}  // namespace
}  // namespace skinsim::driver

// A recommendation's comparison panel: every crop window shows the recommended frame's
// difference from the reference and, when the best is another configuration, from the best,
// so the window found against the best shows the difference it was found in.
#include "driver/sweep/sweep_crops.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "driver/frame/reference_cache.h"
#include "image/image.h"
#include "tests/image/test_image.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;

bool shows(const results::CropWindow& w, const std::string& what) {
  return std::any_of(w.images.begin(), w.images.end(),
                     [&](const auto& image) { return image.first == what; });
}

TEST(SweepCrops, WindowsShowTheDifferenceFromTheBestToo) {
  const fs::path dir = fs::temp_directory_path() / ("skinsim_crops_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "refs");
  fs::create_directories(dir / "configs");
  const image::Image reference = image::testing::pattern_image(256, 192);
  image::save_png(reference, dir / "refs/ref.png");
  image::save_mask_png(image::Mask::filled(256, 192, 255),
                       dir / reference_mask_path("refs/ref.png"));
  results::SweepTable table;
  for (const char* id : {"chosen", "best"}) {
    results::ConfigResult r;
    r.id = id;
    r.frame_image = std::string("configs/") + id + ".png";
    r.reference_image = "refs/ref.png";
    image::save_png(image::testing::add_noise(reference, id[0] == 'c' ? 0.3f : 0.05f, id[0]),
                    dir / r.frame_image);
    table.rows.push_back(r);
  }
  reports::Recommendation rec;
  rec.chosen = 0;
  rec.best = 1;
  std::vector<results::ComparisonPanel> panels = write_comparison_panels(table, {rec}, dir, true);
  ASSERT_EQ(panels.size(), 1u);
  const auto found_against_best =
      std::find_if(panels[0].windows.begin(), panels[0].windows.end(), [](const auto& w) {
        return w.why.find("largest difference from the best") != std::string::npos;
      });
  ASSERT_NE(found_against_best, panels[0].windows.end());
  EXPECT_TRUE(shows(*found_against_best, "|recommended - best| x 8"));
  EXPECT_TRUE(shows(*found_against_best, "|recommended - reference| x 8"));
  for (const auto& [what, path] : found_against_best->images) {
    EXPECT_TRUE(fs::exists(dir / path)) << path;
  }
  // The best recommended: one difference, against the reference.
  rec.chosen = 1;
  panels = write_comparison_panels(table, {rec}, dir, true);
  ASSERT_EQ(panels.size(), 1u);
  for (const results::CropWindow& w : panels[0].windows) {
    EXPECT_FALSE(shows(w, "|recommended - best| x 8")) << w.why;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace skinsim::driver

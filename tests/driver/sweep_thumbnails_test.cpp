#include "driver/sweep/sweep_thumbnails.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "io/read_file.h"
#include "reports/html_text.h"
#include "tests/image/test_image.h"

namespace skinsim::driver {
namespace {

namespace fs = std::filesystem;

// A configuration's thumbnail made from its pixels in memory (sweep_run.cpp) is the one
// write_thumbnails makes from its PNG, byte for byte, and counts as up to date there.
TEST(SweepThumbnails, MadeWithTheImageAsFromItsPng) {
  const fs::path dir = fs::temp_directory_path() / ("skinsim_thumbs_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "configs");
  const std::string image = "configs/a_frame.png";
  // Between bytes and beyond [0,1], so the thumbnail differs unless it is made from the bytes.
  image::Image pixels = image::testing::add_noise(image::testing::pattern_image(700, 300), 0.4f);
  for (glm::vec3& p : pixels.rgb) p = p * 1.2f - 0.1f;
  write_image_and_thumbnail(pixels, dir, image);
  const fs::path thumb = dir / reports::thumbnail_path(image);
  const std::string from_memory = io::read_regular_file(thumb, "thumbnail");
  const auto written = fs::last_write_time(thumb);

  results::SweepTable table;
  table.rows.emplace_back();
  table.rows.back().frame_image = image;
  write_thumbnails(table, dir);
  EXPECT_EQ(fs::last_write_time(thumb), written) << "rewritten: not taken as up to date";

  fs::remove(thumb);
  write_thumbnails(table, dir);
  const std::string from_png = io::read_regular_file(thumb, "thumbnail");
  EXPECT_FALSE(from_png.empty());
  EXPECT_TRUE(from_png == from_memory) << "the thumbnail differs from the PNG's";
  EXPECT_EQ(image::load_png(thumb).width, kThumbnailWidth);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace skinsim::driver

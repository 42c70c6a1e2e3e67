// PNG writing on a full disk: the failure is reported and a truncated PNG never replaces the
// previous one.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "full_disk.h"
#include "image/image.h"
#include "io/read_file.h"
#include "scratch_dir.h"

namespace skinsim::io {
namespace {

namespace fs = std::filesystem;

image::Image noise(int size) {
  image::Image image = image::Image::filled(size, size, glm::vec3(0.0f));
  unsigned state = 12345;
  for (glm::vec3& p : image.rgb) {  // incompressible, so the PNG is large
    for (int c = 0; c < 3; ++c) {
      state = state * 1664525u + 1013904223u;
      p[c] = static_cast<float>(state >> 24) / 255.0f;
    }
  }
  return image;
}

TEST(PngFullDisk, FailureIsReportedAndOldImageKept) {
  const fs::path dir = testing::make_scratch_dir();
  const fs::path path = dir / "frame.png";
  image::save_png(image::Image::filled(8, 8, glm::vec3(0.5f)), path);
  const std::string previous = testing::read_whole(path);

  const std::string error =
      testing::error_on_full_disk(16 * 1024, [&] { image::save_png(noise(256), path); });
  EXPECT_NE(error.find(path.string()), std::string::npos) << error;
  EXPECT_NE(error.find("File too large"), std::string::npos) << error;
  EXPECT_EQ(testing::read_whole(path), previous);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);

  // With room, the same image is written and reads back whole.
  image::save_png(noise(256), path);
  const image::Image expected = noise(256);
  const image::Image read = image::load_png(path);
  ASSERT_EQ(read.rgb.size(), expected.rgb.size());
  for (std::size_t i = 0; i < read.rgb.size(); ++i) {
    ASSERT_NEAR(read.rgb[i].x, expected.rgb[i].x, 1e-6f) << "pixel " << i;
    ASSERT_NEAR(read.rgb[i].z, expected.rgb[i].z, 1e-6f) << "pixel " << i;
  }
}

TEST(PngRead, FifoOrDeviceIsRefusedWithoutBlocking) {
  const fs::path dir = testing::make_scratch_dir();
  ASSERT_EQ(::mkfifo((dir / "frame.png").c_str(), 0600), 0);
  EXPECT_THROW(image::load_png(dir / "frame.png"), InputError);
  EXPECT_THROW(image::load_png("/dev/zero"), InputError);
}

}  // namespace
}  // namespace skinsim::io

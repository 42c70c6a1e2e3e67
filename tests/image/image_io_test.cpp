#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <glm/common.hpp>
#include <limits>
#include <string>
#include <vector>

#include "image/error.h"
#include "image/image.h"
#include "image/png_encode.h"
#include "io/read_file.h"
#include "tests/image/test_image.h"
#include "util/unorm8.h"

namespace skinsim::image {
namespace {

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("skinsim_image_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

using ImageIo = TempDir;

TEST_F(ImageIo, PngRoundTripKeepsEightBitValues) {
  Image image = testing::pattern_image(37, 23);
  for (glm::vec3& p : image.rgb) p = glm::round(p * 255.0f) / 255.0f;  // representable
  const auto path = dir_ / "pattern.png";
  save_png(image, path);
  const Image loaded = load_png(path);
  ASSERT_EQ(loaded.width, 37);
  ASSERT_EQ(loaded.height, 23);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(loaded.rgb[i][c], image.rgb[i][c], 1e-6);
  }
  // Only the finished file is left: the temporary was renamed over it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_),
                          std::filesystem::directory_iterator()),
            1);
}

// A frame read back from its PNG is the frame that was written, bit for bit: every byte k
// decodes to k / 255 as the emulator stores it, so FLIP of a saved frame equals FLIP of the
// frame in memory (k * (1/255), OpenImageIO's decoding, is one ulp off for 126 of the 256).
TEST_F(ImageIo, EightBitPngReadsBackBitForBit) {
  Image image = Image::filled(256, 1, glm::vec3(0.0f));
  for (int k = 0; k < 256; ++k) {
    image.rgb[k] = glm::vec3(kUnorm8Value[k], kUnorm8Value[255 - k], kUnorm8Value[k / 2]);
  }
  const auto path = dir_ / "bytes.png";
  save_png(image, path);
  const Image loaded = load_png(path);
  for (int k = 0; k < 256; ++k) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(std::bit_cast<std::uint32_t>(loaded.rgb[k][c]),
                std::bit_cast<std::uint32_t>(image.rgb[k][c]))
          << "byte " << k << " channel " << c;
    }
  }
}

// round_to_saved_png gives what load_png reads from save_png's file, bit for bit, for values
// between bytes, on the halves between two, out of range, -0 and NaN: the sweep makes its
// thumbnails from it instead of decoding the PNG it has just written.
TEST_F(ImageIo, RoundToSavedPngIsWhatLoadPngReads) {
  Image image = testing::add_noise(testing::pattern_image(61, 17), 0.3f);
  const float specials[] = {-0.5f,
                            -0.0f,
                            1.5f,
                            std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity(),
                            0.5f / 255.0f,
                            127.5f / 255.0f,
                            std::nextafter(127.5f / 255.0f, 0.0f)};
  for (std::size_t i = 0; i < std::size(specials); ++i) image.rgb[i] = glm::vec3(specials[i]);
  const auto path = dir_ / "noisy.png";
  save_png(image, path);
  const Image loaded = load_png(path);
  // save_png_and_round does both at once: the same file, the same rounded values.
  Image saved_and_rounded = image;
  save_png_and_round(saved_and_rounded, dir_ / "noisy_rounded.png");
  EXPECT_EQ(io::read_regular_file(dir_ / "noisy_rounded.png", "png"),
            io::read_regular_file(path, "png"));
  round_to_saved_png(image);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(std::bit_cast<std::uint32_t>(image.rgb[i][c]),
                std::bit_cast<std::uint32_t>(loaded.rgb[i][c]))
          << "pixel " << i << " channel " << c;
      ASSERT_EQ(std::bit_cast<std::uint32_t>(saved_and_rounded.rgb[i][c]),
                std::bit_cast<std::uint32_t>(loaded.rgb[i][c]))
          << "pixel " << i << " channel " << c << " (save_png_and_round)";
    }
  }
}

TEST_F(ImageIo, SaveClampsOutOfRangeValues) {
  Image image = Image::filled(2, 1, glm::vec3(0.0f));
  image.rgb[0] = glm::vec3(-0.5f, 1.5f, std::nanf(""));
  image.rgb[1] = glm::vec3(0.5f);
  const auto path = dir_ / "clamped.png";
  save_png(image, path);
  const Image loaded = load_png(path);
  EXPECT_EQ(loaded.rgb[0], glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_NEAR(loaded.rgb[1].r, 128.0f / 255.0f, 1e-6);  // 127.5 rounds up
}

// Rounding to bytes is lround's: a product just below a half rounds down (0.49999997 + 0.5
// in float rounds up to 1), a half rounds up.
TEST_F(ImageIo, SaveRoundsToTheNearestByte) {
  Image image = Image::filled(3, 1, glm::vec3(0.0f));
  image.rgb[0] = glm::vec3(0.0019607842f);  // x 255 = 0.49999997f
  image.rgb[1] = glm::vec3(0.5f / 255.0f);  // x 255 = 0.5
  image.rgb[2] = glm::vec3(254.49998f / 255.0f);
  const auto path = dir_ / "rounding.png";
  save_png(image, path);
  const Image loaded = load_png(path);
  EXPECT_EQ(loaded.rgb[0].r, 0.0f);
  EXPECT_EQ(loaded.rgb[1].r, kUnorm8Value[1]);
  EXPECT_EQ(loaded.rgb[2].r, kUnorm8Value[254]);
}

TEST_F(ImageIo, AlphaDoesNotScaleColour) {
  // A LUT's alpha is a data channel: colour must be written and read back unpremultiplied.
  const std::vector<std::uint8_t> rgba{200, 100, 50, 64};
  const auto path = dir_ / "rgba.png";
  write_png_u8(path, 1, 1, 4, rgba);
  const Image loaded = load_png(path);
  EXPECT_NEAR(loaded.rgb[0].r, 200.0f / 255.0f, 1e-6);
  EXPECT_NEAR(loaded.rgb[0].g, 100.0f / 255.0f, 1e-6);
  EXPECT_NEAR(loaded.rgb[0].b, 50.0f / 255.0f, 1e-6);
}

void write_bytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

// A 16-bit PNG (made with Python's zlib: 2x1 RGB, (0, 65535, 32768) and (1, 257, 65534)) reads
// as its code values over 65535, with no gamma applied.
TEST_F(ImageIo, SixteenBitPngReadsCodeValues) {
  const std::vector<unsigned char> png = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49,
      0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x10, 0x02,
      0x00, 0x00, 0x00, 0x2b, 0xd0, 0x34, 0x9e, 0x00, 0x00, 0x00, 0x15, 0x49, 0x44,
      0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0x60, 0xf8, 0xff, 0xbf, 0x81, 0x81, 0x81,
      0x91, 0x91, 0xf1, 0xff, 0x3f, 0x00, 0x1a, 0x02, 0x04, 0x7f, 0xa1, 0x62, 0x4b,
      0x1d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  write_bytes(dir_ / "deep.png", png);
  const Image loaded = load_png(dir_ / "deep.png");
  ASSERT_EQ(loaded.width, 2);
  ASSERT_EQ(loaded.height, 1);
  EXPECT_EQ(loaded.rgb[0], glm::vec3(0.0f, 1.0f, 32768.0f / 65535.0f));
  EXPECT_EQ(loaded.rgb[1], glm::vec3(1.0f / 65535.0f, 257.0f / 65535.0f, 65534.0f / 65535.0f));
}

// A 45-byte greyscale PNG whose header declares 10000x10000 pixels (100 MB decoded, 400 MB as
// floats, and within stb_image's own 1 GB limit) is refused before any decoding, naming the
// file and the size.
TEST_F(ImageIo, RefusesAHeaderDeclaringTooManyPixels) {
  const std::vector<unsigned char> png = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
      0x52, 0x00, 0x00, 0x27, 0x10, 0x00, 0x00, 0x27, 0x10, 0x08, 0x00, 0x00, 0x00, 0x00, 0x9f,
      0x25, 0x3d, 0xfb, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  write_bytes(dir_ / "bomb.png", png);
  try {
    load_png(dir_ / "bomb.png");
    FAIL() << "a 10000x10000 header was accepted";
  } catch (const ImageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bomb.png"), std::string::npos) << message;
    EXPECT_NE(message.find("10000x10000"), std::string::npos) << message;
  }
}

TEST_F(ImageIo, MaskRoundTrip) {
  Mask mask = Mask::filled(5, 4, 0);
  mask.values[3] = 1;
  mask.values[17] = 1;
  const auto path = dir_ / "mask.png";
  save_mask_png(mask, path);
  const Mask loaded = load_mask_png(path);
  EXPECT_EQ(loaded.width, 5);
  EXPECT_EQ(loaded.values, mask.values);
  EXPECT_EQ(loaded.count(), 2u);
}

TEST_F(ImageIo, ErrorsNameTheFile) {
  const auto missing = dir_ / "missing.png";
  try {
    load_png(missing);
    FAIL() << "missing file accepted";
  } catch (const UserError& e) {  // io::InputError: refused before it is read
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
  }
  std::ofstream(dir_ / "garbage.png") << "not a png";
  try {
    load_png(dir_ / "garbage.png");
    FAIL() << "garbage accepted";
  } catch (const ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("garbage.png"), std::string::npos) << e.what();
  }
  const auto no_dir = dir_ / "no_such_dir" / "out.png";
  EXPECT_THROW(save_png(Image::filled(2, 2, glm::vec3(0.5f)), no_dir), UserError);
  Image broken = Image::filled(2, 2, glm::vec3(0.5f));
  broken.rgb.pop_back();
  EXPECT_THROW(save_png(broken, dir_ / "broken.png"), ImageError);
}

// stb_image_write counts a PNG's filtered bytes in an int: larger images are refused with
// the file's name, before any pixel is read.
TEST(PngEncode, RefusesImagesTooLargeForOnePng) {
  try {
    encode_png_u8(40000, 20000, 3, {}, "huge.png");
    FAIL() << "a 40000x20000 RGB image was encoded";
  } catch (const ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("huge.png"), std::string::npos) << e.what();
  }
  EXPECT_GT(encode_png_u8(1, 1, 1, std::vector<std::uint8_t>{7}, "one.png").size, 0u);
}

}  // namespace
}  // namespace skinsim::image

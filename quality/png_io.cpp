#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <string>
#include <system_error>

#include "io/atomic_file.h"
#include "io/read_file.h"
#include "quality/error.h"
#include "quality/image.h"
#include "quality/png_encode.h"
#include "util/parallel_pixels.h"
#include "util/unorm8.h"

namespace skinsim::quality {
namespace {

// The bytes save_png writes, RGB interleaved.
std::vector<std::uint8_t> to_rgb8(const Image& image) {
  std::vector<std::uint8_t> bytes(image.rgb.size() * 3);
  for_each_pixel(image.rgb.size(), [&](std::size_t i) {
    for (int c = 0; c < 3; ++c) bytes[i * 3 + c] = unorm8_nearest(image.rgb[i][c]);
  });
  return bytes;
}

// An 8K 16-bit RGBA PNG is at most ~256 MiB uncompressed; anything larger is not an image
// this project wrote or can use.
constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t{256} << 20;

// Reads all pixels as normalised floats; returns the channel count.
int read_floats(const std::filesystem::path& path, int& width, int& height,
                std::vector<float>& pixels) {
  // A FIFO would block OpenImageIO's open forever, and /dev/zero would be read without end.
  io::require_regular_file(path, "image", kMaxImageFileBytes);
  // Keep colour values as stored: without this OpenImageIO premultiplies them by alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path.string(), &config);
  if (!input) {
    throw QualityError("cannot open image '" + path.string() + "': " + OIIO::geterror());
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
    throw QualityError("image '" + path.string() + "' has no pixels");
  }
  width = spec.width;
  height = spec.height;
  const int channels = spec.nchannels;
  const std::size_t count = static_cast<std::size_t>(width) * height * channels;
  const auto read = [&](OIIO::TypeDesc type, void* data) {
    if (!input->read_image(0, 0, 0, channels, type, data)) {
      throw QualityError("cannot read pixels of '" + path.string() + "': " + input->geterror());
    }
  };
  pixels.resize(count);
  if (spec.format == OIIO::TypeDesc::UINT8) {
    // Byte k becomes k / 255 exactly as the emulator stores it (util/unorm8.h). OpenImageIO 2.4's
    // own conversion multiplies by 1/255, which is one ulp off for 126 of the 256 bytes, so
    // a frame read back from its PNG would differ from the frame that was written.
    std::vector<std::uint8_t> bytes(count);
    read(OIIO::TypeDesc::UINT8, bytes.data());
    std::transform(bytes.begin(), bytes.end(), pixels.begin(),
                   [](std::uint8_t k) { return kUnorm8Value[k]; });
  } else {
    read(OIIO::TypeDesc::FLOAT, pixels.data());
  }
  input->close();
  return channels;
}

}  // namespace

Image load_png(const std::filesystem::path& path) {
  Image image;
  std::vector<float> pixels;
  const int channels = read_floats(path, image.width, image.height, pixels);
  image.rgb.resize(image.pixel_count());
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const float* p = &pixels[i * channels];
    // 1 = grey, 2 = grey + alpha: replicate grey; 3 or more: the first three are RGB.
    image.rgb[i] = channels < 3 ? glm::vec3(p[0]) : glm::vec3(p[0], p[1], p[2]);
  }
  return image;
}

void save_png(const Image& image, const std::filesystem::path& path) {
  if (image.rgb.size() != image.pixel_count()) {
    throw QualityError("cannot write '" + path.string() + "': image holds " +
                       std::to_string(image.rgb.size()) + " pixels, expected " +
                       std::to_string(image.width) + "x" + std::to_string(image.height));
  }
  write_png_u8(path, image.width, image.height, 3, to_rgb8(image));
}

void round_to_saved_png(Image& image) {
  for_each_pixel(image.rgb.size(), [&](std::size_t i) {
    for (int c = 0; c < 3; ++c) image.rgb[i][c] = kUnorm8Value[unorm8_nearest(image.rgb[i][c])];
  });
}

Mask load_mask_png(const std::filesystem::path& path) {
  Mask mask;
  std::vector<float> pixels;
  const int channels = read_floats(path, mask.width, mask.height, pixels);
  mask.values.resize(static_cast<std::size_t>(mask.width) * mask.height);
  for (std::size_t i = 0; i < mask.values.size(); ++i) {
    mask.values[i] = pixels[i * channels] != 0.0f ? 1 : 0;
  }
  return mask;
}

void save_mask_png(const Mask& mask, const std::filesystem::path& path) {
  std::vector<std::uint8_t> bytes(mask.values.size());
  std::transform(mask.values.begin(), mask.values.end(), bytes.begin(),
                 [](std::uint8_t v) -> std::uint8_t { return v != 0 ? 255 : 0; });
  write_png_u8(path, mask.width, mask.height, 1, bytes);
}

void write_png_u8(const std::filesystem::path& path, int width, int height, int channels,
                  std::span<const std::uint8_t> data) {
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4) {
    throw QualityError("cannot write '" + path.string() + "': invalid size " +
                       std::to_string(width) + "x" + std::to_string(height) + "x" +
                       std::to_string(channels));
  }
  if (data.size() != static_cast<std::size_t>(width) * height * channels) {
    throw QualityError("cannot write '" + path.string() + "': " + std::to_string(data.size()) +
                       " bytes given for " + std::to_string(width) + "x" + std::to_string(height) +
                       "x" + std::to_string(channels));
  }
  // Encoded in memory, then written by the checked atomic writer: a full disk is reported
  // and a truncated PNG never replaces a good one.
  const std::vector<unsigned char> png =
      encode_png_u8(width, height, channels, data, path.string());
  io::write_file_atomically(
      path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace skinsim::quality

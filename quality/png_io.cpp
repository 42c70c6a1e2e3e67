#include <stb/stb_image.h>

#include <algorithm>
#include <memory>
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
// The pixels a header may declare: 8K x 8K. A small file can declare far more (a
// decompression bomb); it is refused before anything is decoded.
constexpr long long kMaxImagePixels = 8192LL * 8192LL;

// Reads all pixels as normalised floats; returns the channel count. stb_image (libstb, which
// the glTF loader decodes with too) keeps values as stored: no gamma, no premultiplied alpha.
int read_floats(const std::filesystem::path& path, int& width, int& height,
                std::vector<float>& pixels) {
  // A FIFO would block, and /dev/zero would be read without end.
  const std::string file = io::read_regular_file(path, "image", kMaxImageFileBytes);
  const auto* bytes = reinterpret_cast<const stbi_uc*>(file.data());
  const int size = static_cast<int>(file.size());
  int channels = 0;
  if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
    throw QualityError("cannot open image '" + path.string() + "': " + stbi_failure_reason());
  }
  if (width <= 0 || height <= 0 || channels <= 0) {
    throw QualityError("image '" + path.string() + "' has no pixels");
  }
  if (static_cast<long long>(width) * height > kMaxImagePixels) {
    throw QualityError("image '" + path.string() + "' declares " + std::to_string(width) + "x" +
                       std::to_string(height) + " pixels, more than the 8192x8192 skinsim reads");
  }
  const std::size_t count = static_cast<std::size_t>(width) * height * channels;
  pixels.resize(count);
  int w = 0, h = 0, n = 0;
  const auto check = [&](const void* decoded) {
    if (!decoded || w != width || h != height || n != channels) {
      throw QualityError("cannot read pixels of '" + path.string() +
                         "': " + (decoded ? "header and pixels disagree" : stbi_failure_reason()));
    }
  };
  if (stbi_is_16_bit_from_memory(bytes, size)) {
    const std::unique_ptr<stbi_us, decltype(&stbi_image_free)> decoded(
        stbi_load_16_from_memory(bytes, size, &w, &h, &n, 0), stbi_image_free);
    check(decoded.get());
    std::transform(decoded.get(), decoded.get() + count, pixels.begin(),
                   [](stbi_us k) { return static_cast<float>(k) / 65535.0f; });
  } else {
    // Byte k becomes k / 255 exactly as the emulator stores it (util/unorm8.h), so a frame
    // read back from its PNG is the frame that was written.
    const std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> decoded(
        stbi_load_from_memory(bytes, size, &w, &h, &n, 0), stbi_image_free);
    check(decoded.get());
    std::transform(decoded.get(), decoded.get() + count, pixels.begin(),
                   [](stbi_uc k) { return kUnorm8Value[k]; });
  }
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

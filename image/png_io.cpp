#include <stb/stb_image.h>

#include <algorithm>
#include <memory>
#include <string>
#include <system_error>

#include "image/error.h"
#include "image/image.h"
#include "image/png_encode.h"
#include "io/atomic_file.h"
#include "io/read_file.h"
#include "util/parallel_pixels.h"
#include "util/unorm8.h"

namespace skinsim::image {
namespace {

// The bytes save_png writes, RGB interleaved. With `rounded` (which may be `image` itself:
// each value is read before it is written), also the values load_png reads back from them.
std::vector<std::uint8_t> to_rgb8(const Image& image, Image* rounded = nullptr) {
  const std::size_t count = image.rgb.size() * 3;
  std::vector<std::uint8_t> bytes(count);
  const float* values = &image.rgb.data()->x;  // glm::vec3 is three packed floats
  float* rounded_values = rounded ? &rounded->rgb.data()->x : nullptr;
  for_each_block(count, [&](std::size_t begin, std::size_t end) {
    unorm8_nearest(values + begin, end - begin, &bytes[begin],
                   rounded_values ? rounded_values + begin : nullptr);
  });
  return bytes;
}

void check_pixel_count(const Image& image, const std::filesystem::path& path) {
  if (image.rgb.size() != image.pixel_count()) {
    throw ImageError("cannot write '" + path.string() + "': image holds " +
                     std::to_string(image.rgb.size()) + " pixels, expected " +
                     std::to_string(image.width) + "x" + std::to_string(image.height));
  }
}

// An 8K 16-bit RGBA PNG is at most ~256 MiB uncompressed; anything larger is not an image
// this project wrote or can use.
constexpr std::uintmax_t kMaxImageFileBytes = std::uintmax_t{256} << 20;
// The pixels a header may declare: 8K x 8K. A small file can declare far more (a
// decompression bomb); it is refused before anything is decoded.
constexpr long long kMaxImagePixels = 8192LL * 8192LL;

// An image as stb_image (libstb, which the glTF loader decodes with too) decodes it: the
// samples as stored, 8 or 16 bits, with no gamma and no premultiplied alpha.
class DecodedImage {
 public:
  explicit DecodedImage(const std::filesystem::path& path) {
    // A FIFO would block, and /dev/zero would be read without end.
    const std::string file = io::read_regular_file(path, "image", kMaxImageFileBytes);
    const auto* bytes = reinterpret_cast<const stbi_uc*>(file.data());
    const int size = static_cast<int>(file.size());
    if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
      throw ImageError("cannot open image '" + path.string() + "': " + stbi_failure_reason());
    }
    if (width <= 0 || height <= 0 || channels <= 0) {
      throw ImageError("image '" + path.string() + "' has no pixels");
    }
    if (static_cast<long long>(width) * height > kMaxImagePixels) {
      throw ImageError("image '" + path.string() + "' declares " + std::to_string(width) + "x" +
                       std::to_string(height) + " pixels, more than the 8192x8192 skinsim reads");
    }
    int w = 0, h = 0, n = 0;
    deep_ = stbi_is_16_bit_from_memory(bytes, size);
    samples_.reset(deep_ ? static_cast<void*>(stbi_load_16_from_memory(bytes, size, &w, &h, &n, 0))
                         : static_cast<void*>(stbi_load_from_memory(bytes, size, &w, &h, &n, 0)));
    if (!samples_ || w != width || h != height || n != channels) {
      throw ImageError("cannot read pixels of '" + path.string() +
                       "': " + (samples_ ? "header and pixels disagree" : stbi_failure_reason()));
    }
  }

  // Channel `c` of pixel `i` normalised: code value / max code. Byte k is k / 255 exactly as
  // the emulator stores it (util/unorm8.h), so a frame read back from its PNG is the frame
  // that was written.
  float value(std::size_t i, int c) const {
    const std::size_t at = i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c);
    return deep_ ? static_cast<float>(static_cast<const stbi_us*>(samples_.get())[at]) / 65535.0f
                 : kUnorm8Value[static_cast<const stbi_uc*>(samples_.get())[at]];
  }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }

  int width = 0;
  int height = 0;
  int channels = 0;

 private:
  bool deep_ = false;  // 16 bits a sample
  std::unique_ptr<void, decltype(&stbi_image_free)> samples_{nullptr, stbi_image_free};
};

}  // namespace

Image load_png(const std::filesystem::path& path) {
  const DecodedImage decoded(path);
  Image image;
  image.width = decoded.width;
  image.height = decoded.height;
  image.rgb.resize(decoded.pixel_count());
  // 1 = grey, 2 = grey + alpha: replicate grey; 3 or more: the first three are RGB.
  const bool grey = decoded.channels < 3;
  for_each_pixel(image.rgb.size(), [&](std::size_t i) {
    image.rgb[i] = grey ? glm::vec3(decoded.value(i, 0))
                        : glm::vec3(decoded.value(i, 0), decoded.value(i, 1), decoded.value(i, 2));
  });
  return image;
}

void save_png(const Image& image, const std::filesystem::path& path) {
  check_pixel_count(image, path);
  write_png_u8(path, image.width, image.height, 3, to_rgb8(image));
}

EncodedPng encode_png(const Image& image, const std::string& what) {
  check_pixel_count(image, what);
  return encode_png_u8(image.width, image.height, 3, to_rgb8(image), what);
}

EncodedPng save_png_and_round(Image& image, const std::filesystem::path& path) {
  check_pixel_count(image, path);
  return write_png_u8(path, image.width, image.height, 3, to_rgb8(image, &image));
}

void round_to_saved_png(Image& image) {
  to_rgb8(image, &image);
}

Mask load_mask_png(const std::filesystem::path& path) {
  const DecodedImage decoded(path);
  Mask mask;
  mask.width = decoded.width;
  mask.height = decoded.height;
  mask.values.resize(decoded.pixel_count());
  for (std::size_t i = 0; i < mask.values.size(); ++i) {
    mask.values[i] = decoded.value(i, 0) != 0.0f ? 1 : 0;
  }
  return mask;
}

namespace {

std::vector<std::uint8_t> mask_bytes(const Mask& mask) {
  std::vector<std::uint8_t> bytes(mask.values.size());
  std::transform(mask.values.begin(), mask.values.end(), bytes.begin(),
                 [](std::uint8_t v) -> std::uint8_t { return v != 0 ? 255 : 0; });
  return bytes;
}

}  // namespace

void save_mask_png(const Mask& mask, const std::filesystem::path& path) {
  write_png_u8(path, mask.width, mask.height, 1, mask_bytes(mask));
}

EncodedPng encode_mask_png(const Mask& mask, const std::string& what) {
  return encode_png_u8(mask.width, mask.height, 1, mask_bytes(mask), what);
}

EncodedPng write_png_u8(const std::filesystem::path& path, int width, int height, int channels,
                        std::span<const std::uint8_t> data) {
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4) {
    throw ImageError("cannot write '" + path.string() + "': invalid size " + std::to_string(width) +
                     "x" + std::to_string(height) + "x" + std::to_string(channels));
  }
  if (data.size() != static_cast<std::size_t>(width) * height * channels) {
    throw ImageError("cannot write '" + path.string() + "': " + std::to_string(data.size()) +
                     " bytes given for " + std::to_string(width) + "x" + std::to_string(height) +
                     "x" + std::to_string(channels));
  }
  // Encoded in memory, then written by the checked atomic writer: a full disk is reported
  // and a truncated PNG never replaces a good one.
  EncodedPng png = encode_png_u8(width, height, channels, data, path.string());
  io::write_file_atomically(path, png.bytes());
  return png;
}

}  // namespace skinsim::image

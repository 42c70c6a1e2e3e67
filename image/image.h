// Images as a user sees them: display-referred, sRGB-encoded values in [0,1], plus pixel masks
// and PNG input/output (writes are encoded in memory and written by io::write_file_atomically).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "image/png_encode.h"

namespace skinsim::image {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> rgb;  // row-major, top row first, sRGB-encoded in [0,1]

  static Image filled(int width, int height, const glm::vec3& value);
  std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }
  glm::vec3& at(int x, int y) { return rgb[static_cast<std::size_t>(y) * width + x]; }
  const glm::vec3& at(int x, int y) const { return rgb[static_cast<std::size_t>(y) * width + x]; }
};

// Which pixels a statistic counts: 1 = counts, 0 = ignored (e.g. skin vs background).
struct Mask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> values;  // row-major, one byte per pixel

  static Mask filled(int width, int height, std::uint8_t value);
  std::size_t count() const;  // number of pixels that count
};

// A per-pixel scalar field (an SSIM map, a FLIP error map), row-major.
struct ScalarMap {
  int width = 0;
  int height = 0;
  std::vector<float> values;
};

// Reads an 8- or 16-bit image (PNG or any format stb_image reads) of at most 8192x8192
// pixels; grey is replicated to RGB, alpha is dropped. Values are the stored code values /
// max code, i.e. sRGB-encoded.
Image load_png(const std::filesystem::path& path);
// Writes 8-bit RGB, each value clamped to [0,1] and rounded to the nearest 1/255.
void save_png(const Image& image, const std::filesystem::path& path);
// Makes `image` what load_png reads back from the PNG save_png writes of it, bit for bit,
// without the file: each value becomes its nearest byte's (util/unorm8.h).
void round_to_saved_png(Image& image);
// save_png, then round_to_saved_png, with each value rounded once for both. Returns the bytes
// written (png_encode.h).
EncodedPng save_png_and_round(Image& image, const std::filesystem::path& path);

// Masks as 8-bit grey PNGs: any non-zero value counts.
Mask load_mask_png(const std::filesystem::path& path);
void save_mask_png(const Mask& mask, const std::filesystem::path& path);

// Writes `channels` interleaved 8-bit channels (1..4) of a width x height image: encoded in
// memory, then written with io::write_file_atomically (checked, temp file + rename),
// so readers never see a half-written file. Returns the bytes written.
EncodedPng write_png_u8(const std::filesystem::path& path, int width, int height, int channels,
                        std::span<const std::uint8_t> data);

}  // namespace skinsim::image

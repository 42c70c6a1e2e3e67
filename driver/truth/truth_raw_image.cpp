// The raw exchange file of driver/truth/truth_image.h, shared by skinsim and skinsim-exr.
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "driver/truth/truth_image.h"
#include "util/user_error.h"

namespace skinsim::driver {

namespace {

constexpr char kMagic[8] = {'S', 'K', 'F', '3', '2', 'R', 'G', 'B'};
static_assert(std::endian::native == std::endian::little, "the raw file is little-endian");

}  // namespace

void write_raw_image(const LinearImage& image, const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  const std::uint32_t size[2] = {static_cast<std::uint32_t>(image.width),
                                 static_cast<std::uint32_t>(image.height)};
  out.write(kMagic, sizeof kMagic);
  out.write(reinterpret_cast<const char*>(size), sizeof size);
  out.write(reinterpret_cast<const char*>(image.rgb.data()),
            static_cast<std::streamsize>(image.rgb.size() * sizeof(glm::vec3)));
  out.close();
  if (!out) throw UserError("cannot write " + path.string());
}

LinearImage read_raw_image(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  std::uint32_t size[2] = {0, 0};
  in.read(magic, sizeof magic);
  in.read(reinterpret_cast<char*>(size), sizeof size);
  if (!in || std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
    throw UserError(path.string() + ": not a skinsim raw float image");
  }
  constexpr std::uint32_t kMaxSide = 16384;
  if (size[0] == 0 || size[1] == 0 || size[0] > kMaxSide || size[1] > kMaxSide) {
    throw UserError(path.string() + ": image size " + std::to_string(size[0]) + "x" +
                    std::to_string(size[1]) + " out of range (1..16384 a side)");
  }
  LinearImage image{static_cast<int>(size[0]), static_cast<int>(size[1]), {}};
  image.rgb.resize(static_cast<std::size_t>(size[0]) * size[1]);
  in.read(reinterpret_cast<char*>(image.rgb.data()),
          static_cast<std::streamsize>(image.rgb.size() * sizeof(glm::vec3)));
  if (!in) throw UserError(path.string() + ": truncated raw float image");
  return image;
}

}  // namespace skinsim::driver

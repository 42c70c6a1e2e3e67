#include "image/png_encode.h"

#include <libdeflate.h>

#include <climits>
#include <cstdlib>
#include <memory>

#include "image/error.h"

namespace skinsim::image {
namespace {

// libdeflate's zlib stream, in memory stb_image_write frees with free().
unsigned char* deflate_level_1(const unsigned char* data, int size, int* out_size, int) {
  const std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor(
      libdeflate_alloc_compressor(1), libdeflate_free_compressor);
  if (!compressor) return nullptr;
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor.get(), size);
  auto* out = static_cast<unsigned char*>(std::malloc(bound));
  if (!out) return nullptr;
  const std::size_t written = libdeflate_zlib_compress(compressor.get(), data, size, out, bound);
  if (written == 0 || written > INT_MAX) {
    std::free(out);
    return nullptr;
  }
  *out_size = static_cast<int>(written);
  return out;
}

}  // namespace
}  // namespace skinsim::image

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC  // this file's own copy, beside libstb's default-built one
#define STBI_WRITE_NO_STDIO
#define STBIW_ZLIB_COMPRESS skinsim::image::deflate_level_1
#define STBIW_CRC32(buffer, size) static_cast<unsigned>(libdeflate_crc32(0, buffer, size))
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace skinsim::image {

EncodedPng encode_png_u8(int width, int height, int channels, std::span<const std::uint8_t> data,
                         const std::string& what) {
  // stb_image_write counts the filtered rows (one filter byte each) in an int.
  if ((static_cast<long long>(width) * channels + 1) * height > INT_MAX) {
    throw ImageError("cannot write '" + what + "': " + std::to_string(width) + "x" +
                     std::to_string(height) + "x" + std::to_string(channels) +
                     " is too large for one PNG");
  }
  // The Sub filter on every row, set once: stb_image_write's choice is a global it reads.
  [[maybe_unused]] static const bool sub_filter = [] {
    stbi_write_force_png_filter = 1;
    return true;
  }();
  int size = 0;
  EncodedPng png;
  png.data.reset(
      stbi_write_png_to_mem(data.data(), width * channels, width, height, channels, &size));
  if (!png.data) throw ImageError("cannot write '" + what + "': out of memory encoding the PNG");
  png.size = static_cast<std::size_t>(size);
  return png;
}

}  // namespace skinsim::image

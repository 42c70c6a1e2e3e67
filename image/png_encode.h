// PNG encoding of 8-bit images into memory: stb_image_write's PNG container (libstb-dev) with
// its deflate stream and chunk checksums from libdeflate (libdeflate-dev).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace skinsim::image {

// A PNG file's bytes, in the buffer stb_image_write encoded them into (no copy).
struct EncodedPng {
  std::unique_ptr<unsigned char, decltype(&std::free)> data{nullptr, std::free};
  std::size_t size = 0;
  std::string_view bytes() const { return {reinterpret_cast<const char*>(data.get()), size}; }
};

// The PNG of `width` x `height` pixels of `channels` (1 to 4) interleaved bytes, rows top
// first. Every row uses the Sub filter and the stream is deflated at libdeflate's level 1:
// measured on a 2048x1536 frame, 34 ms and 1.35 MB for the deflate against 54 ms and 1.56 MB
// for zlib's level 1 (docs/performance-log.md); a sweep writes two such images per configuration.
// Throws ImageError (naming `what`) for sizes a PNG written so cannot hold.
EncodedPng encode_png_u8(int width, int height, int channels, std::span<const std::uint8_t> data,
                         const std::string& what);

struct Image;
struct Mask;
// The bytes save_png and save_mask_png (image.h) write, for a writer that places the file
// itself (the reference store, which never follows a symlink: io::replace_file_entry).
EncodedPng encode_png(const Image& image, const std::string& what);
EncodedPng encode_mask_png(const Mask& mask, const std::string& what);

}  // namespace skinsim::image

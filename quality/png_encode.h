// PNG encoding of 8-bit images into memory: stb_image_write's PNG container (libstb-dev) with
// its deflate stream and chunk checksums from libdeflate (libdeflate-dev).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace skinsim::quality {

// The PNG of `width` x `height` pixels of `channels` (1 to 4) interleaved bytes, rows top
// first. Every row uses the Sub filter and the stream is deflated at libdeflate's level 1:
// measured on a 2048x1536 frame, 34 ms and 1.35 MB for the deflate against 54 ms and 1.56 MB
// for zlib's level 1 (docs/performance.md); a sweep writes two such images per configuration.
// Throws QualityError (naming `what`) for sizes a PNG written so cannot hold.
std::vector<unsigned char> encode_png_u8(int width, int height, int channels,
                                         std::span<const std::uint8_t> data,
                                         const std::string& what);

}  // namespace skinsim::quality

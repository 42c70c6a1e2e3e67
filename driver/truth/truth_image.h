// Linear HDR images for `skinsim truth`: the path tracer's OpenEXR and any linear image a
// user brings. OpenImageIO reads and writes them, but in a helper program (skinsim-exr,
// driver/truth/truth_exr_tool.cpp), not in skinsim: Debian's OpenImageIO pulls in ~260 shared
// libraries, which every skinsim start would load. The two exchange a raw float file:
//   "SKF32RGB", uint32 width, uint32 height (little-endian), then width x height x 3
//   float32, the top row first.
#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <vector>

#include "image/image.h"

namespace skinsim::driver {

struct LinearImage {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> rgb;  // scene-linear Rec.709, row-major, top row first
};

// The raw exchange file. Reading throws UserError naming the file when it is not one.
void write_raw_image(const LinearImage& image, const std::filesystem::path& path);
LinearImage read_raw_image(const std::filesystem::path& path);

// Any image OpenImageIO reads (EXR, HDR, TIFF, ...), through skinsim-exr; `log` receives the
// helper's messages. Throws UserError naming the file when it cannot be read.
LinearImage read_linear_image(const std::filesystem::path& path, const std::filesystem::path& log);

// As skinsim's frames are seen: sRGB-encoded, clamped to [0,1], rounded to 8 bits (as the
// reference.png a run writes), so the metrics compare like with like.
image::Image display_image(const LinearImage& image);

}  // namespace skinsim::driver

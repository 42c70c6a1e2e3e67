// The LUT as a PNG, apart from the baker so that code which only renders links no image
// library.
#include <string>
#include <vector>

#include "image/image.h"
#include "pipeline/bake/brdf_lut.h"
#include "pipeline/bake/error.h"
#include "util/unorm8.h"

namespace skinsim::bake {

void write_lut_png(const BrdfLut& lut, const std::filesystem::path& path, int level) {
  if (level < 0 || level >= static_cast<int>(lut.levels.size())) {
    throw BakeError("cannot write '" + path.string() + "': LUT has no level " +
                    std::to_string(level) + " (it has " + std::to_string(lut.levels.size()) + ")");
  }
  const LutLevel& l = lut.levels[level];
  std::vector<std::uint8_t> bytes(l.texels.size() * 4);
  for (std::size_t i = 0; i < l.texels.size(); ++i) {
    for (int c = 0; c < 4; ++c) {
      bytes[i * 4 + c] = unorm8_nearest(l.texels[i][c]);
    }
  }
  image::write_png_u8(path, l.width, l.height, 4, bytes);
}

}  // namespace skinsim::bake

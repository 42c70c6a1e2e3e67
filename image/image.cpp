// Image and Mask themselves; their PNG input/output is png_io.cpp (libstb, libdeflate), so code
// that only measures images links no image library.
#include "image/image.h"

#include <algorithm>

namespace skinsim::image {

Image Image::filled(int width, int height, const glm::vec3& value) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<std::size_t>(width) * height, value);
  return image;
}

Mask Mask::filled(int width, int height, std::uint8_t value) {
  Mask mask;
  mask.width = width;
  mask.height = height;
  mask.values.assign(static_cast<std::size_t>(width) * height, value);
  return mask;
}

std::size_t Mask::count() const {
  return static_cast<std::size_t>(
      std::count_if(values.begin(), values.end(), [](std::uint8_t v) { return v != 0; }));
}

}  // namespace skinsim::image

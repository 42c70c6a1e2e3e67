#include "image/resize.h"

#include <stb/stb_image_resize.h>

#include <algorithm>
#include <stdexcept>

#include "util/check.h"

namespace skinsim::image {

Image resized(const Image& image, int width) {
  SKINSIM_CHECK_GE(width, 1);
  SKINSIM_CHECK_GE(image.width, 1);
  SKINSIM_CHECK_GE(image.height, 1);
  const int height =
      std::max(1, static_cast<int>(static_cast<long long>(image.height) * width / image.width));
  Image result = Image::filled(width, height, glm::vec3(0.0f));
  // stb_image_resize's box filter averages the source pixels each output pixel covers (a
  // trapezoid with one-pixel ramps at a non-integer ratio): no aliasing, and no sharpening
  // overshoot, for a thumbnail of a 2048x1536 frame.
  const int ok = stbir_resize_float_generic(&image.rgb.data()->x, image.width, image.height, 0,
                                            &result.rgb.data()->x, width, height, 0, 3,
                                            STBIR_ALPHA_CHANNEL_NONE, 0, STBIR_EDGE_CLAMP,
                                            STBIR_FILTER_BOX, STBIR_COLORSPACE_LINEAR, nullptr);
  if (!ok) throw std::runtime_error("stb_image_resize failed (out of memory)");
  return result;
}

}  // namespace skinsim::image

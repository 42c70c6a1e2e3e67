#include "quality/resize.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <stdexcept>

#include "util/check.h"

namespace skinsim::quality {

Image resized(const Image& image, int width) {
  SKINSIM_CHECK_GE(width, 1);
  SKINSIM_CHECK_GE(image.width, 1);
  SKINSIM_CHECK_GE(image.height, 1);
  const int height =
      std::max(1, static_cast<int>(static_cast<long long>(image.height) * width / image.width));
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  // ImageBuf wraps the pixels without copying; resize only reads them.
  const OIIO::ImageBuf source(spec, const_cast<glm::vec3*>(image.rgb.data()));
  // A box filter as wide as the reduction averages the source pixels each output pixel
  // covers: no aliasing, and 38 ms for a 2048x1536 frame to 320 px against 880 ms for
  // OpenImageIO's default (Blackman-Harris) filter, which is a little sharper.
  const OIIO::ImageBuf out =
      OIIO::ImageBufAlgo::resize(source, "box", 0.0f, OIIO::ROI(0, width, 0, height, 0, 1, 0, 3));
  if (out.has_error()) throw std::runtime_error("OpenImageIO resize failed: " + out.geterror());
  Image result = Image::filled(width, height, glm::vec3(0.0f));
  out.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT,
                 result.rgb.data());
  return result;
}

}  // namespace skinsim::quality

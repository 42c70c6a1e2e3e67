// Resampling display images, e.g. the small thumbnails a report page loads.
#pragma once

#include "image/image.h"

namespace skinsim::image {

// `image` resampled to `width` pixels wide, the height in proportion (at least 1), with
// stb_image_resize (libstb) and a box filter as wide as the reduction (an area average, not point
// sampling, so thin features do not alias away). `width` and the image's size must be at
// least 1.
Image resized(const Image& image, int width);

}  // namespace skinsim::image

// Fixed places a reviewer of skin always looks at, found in the reference frame and its skin
// mask alone (no scene knowledge, so they work for the built-in head and any scan): an eye,
// the lips, the strongest shadow edge and the silhouette. The comparison panels crop them
// beside the windows where the error is worst.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace skinsim::driver {

struct Landmark {
  std::string why;   // what it is and how it was found, for the report
  int x = 0, y = 0;  // its centre, in frame pixels
};

// How much redder ((r - g) / (r + g + b), display values) than the median skin around them
// lips must be. Measured on references at 1024x768: the built-in head's painted lips 0.23;
// LeePerrySmith in one flat skin colour framed on its face, the mouth's crease (reddened by
// diffusion) 0.19; skin of one colour with no reddening 0.
inline constexpr float kLipRedness = 0.05f;

// In order: eye, lips, shadow edge, silhouette; each is left out when the frame does not
// show it (e.g. a scan whose eyes are skin-material has no hole in the mask); `not_found`
// (if given) receives a sentence for the lips when they were looked for and not found.
// Deterministic: ties go to the first pixel in row order.
std::vector<Landmark> find_landmarks(const image::Image& reference, const image::Mask& skin,
                                     std::vector<std::string>* not_found = nullptr);

}  // namespace skinsim::driver

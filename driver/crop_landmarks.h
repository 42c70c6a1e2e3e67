// Fixed places a reviewer of skin always looks at, found in the reference frame and its skin
// mask alone (no scene knowledge, so they work for the built-in head and any scan): an eye,
// the lips, the strongest shadow edge and the silhouette. The comparison panels crop them
// beside the windows where the error is worst.
#pragma once

#include <string>
#include <vector>

#include "quality/image.h"

namespace skinsim::driver {

struct Landmark {
  std::string why;   // what it is and how it was found, for the report
  int x = 0, y = 0;  // its centre, in frame pixels
};

// In order: eye, lips, shadow edge, silhouette; each is left out when the frame does not
// show it (e.g. a scan whose eyes are skin-material has no hole in the mask). Deterministic:
// ties go to the first pixel in row order.
std::vector<Landmark> find_landmarks(const quality::Image& reference, const quality::Mask& skin);

}  // namespace skinsim::driver

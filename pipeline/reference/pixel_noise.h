// Per-pixel rotations of the reference's fixed ray patterns. Jimenez's interleaved gradient
// noise ("Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014):
// a hash of the pixel's coordinates whose values over any 3 x 3 pixels are spread evenly
// over [0, 1), so a pattern rotated by it turns the steps between its rays into fine noise
// that the skin's diffusion averages away. A function of the pixel alone, never of a thread
// or of the order pixels are shaded in: the reference has the same bits for any thread count.
#pragma once

#include <cmath>

namespace skinsim::pipeline::reference {

// In [0, 1). `stream` > 0 decorrelates another pattern at the same pixel: Jimenez's offset of
// 5.588238 pixels per animation frame, taken as one stream per pattern.
inline float interleaved_gradient_noise(int x, int y, int stream = 0) {
  const float fx = static_cast<float>(x) + 5.588238f * static_cast<float>(stream);
  const float fy = static_cast<float>(y) + 5.588238f * static_cast<float>(stream);
  return std::fmod(52.9829189f * std::fmod(0.06711056f * fx + 0.00583715f * fy, 1.0f), 1.0f);
}

}  // namespace skinsim::pipeline::reference

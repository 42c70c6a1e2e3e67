// The sRGB transfer function (IEC 61966-2-1) in single precision, for images skinsim encodes
// for display (the reference, a path-traced truth) and colours a user gives in sRGB. The
// shaders have their own, in the shading language (pipeline/shaders/gamma.h), and FLIP its
// double-precision decode (quality/flip_color.h).
#pragma once

#include <algorithm>
#include <cmath>

namespace skinsim {

// Linear to sRGB-encoded; negative values encode as 0, values above 1 above 1.
inline float srgb_encode(float c) {
  c = std::max(c, 0.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// sRGB-encoded to linear.
inline float srgb_decode(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace skinsim

// Display encoding in the shader (GPU Pro 5: no sRGB hardware on the target, so skin does
// its own gamma): gamma 2.0 (decode = square, encode = sqrt) or the exact sRGB curve.
#pragma once

#include "pipeline/config.h"
#include "shading/shader_lang.h"

namespace skinsim::pipeline::shaders {

namespace sl = sim::sl;

template <GammaMode kMode, class V>
V decode_gamma(const V& c) {
  if constexpr (kMode == GammaMode::kSquare) {
    return c * c;
  } else {  // IEC 61966-2-1 piecewise curve, branch-free
    const V linear_part = c * (1.0f / 12.92f);
    const V power_part = sl::pow((c + 0.055f) * (1.0f / 1.055f), 2.4f);
    return sl::mix(linear_part, power_part, sl::step(V(0.04045f), c));
  }
}

template <GammaMode kMode, class V>
V encode_gamma(const V& c) {
  if constexpr (kMode == GammaMode::kSquare) {
    return sl::sqrt(sl::max(c, V(0.0f)));
  } else {
    const V linear_part = c * 12.92f;
    const V power_part = sl::pow(sl::max(c, V(0.0031308f)), 1.0f / 2.4f) * 1.055f - 0.055f;
    return sl::mix(linear_part, power_part, sl::step(V(0.0031308f), c));
  }
}

}  // namespace skinsim::pipeline::shaders

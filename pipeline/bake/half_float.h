// IEEE 754 binary16 ("half") conversion, as GPUs store RGBA16F texels.
#pragma once

#include <cstdint>

namespace skinsim::bake {

// Rounds to the nearest half, ties to even; handles subnormals, overflow to infinity and NaN.
std::uint16_t float_to_half(float value);
float half_to_float(std::uint16_t bits);

}  // namespace skinsim::bake

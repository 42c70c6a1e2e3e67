// Rounding to IEEE 754 binary16 ("half", FP16): what an RGBA16F texel stores and what a
// mediump shader value holds on a GPU that computes mediump in FP16 (PowerVR: "mediump ...
// represented as 16 bit floating point (FP16)", Imagination's Performance Recommendations,
// "Demystifying Precision").
#pragma once

#include <bit>
#include <cstdint>

namespace skinsim::sim {

// The nearest FP16 value as a float: round to nearest, ties to even, with FP16 subnormals.
// Finite values beyond the largest half saturate to +-65504 (a render target's clamp; GLSL
// ES leaves mediump overflow undefined, and saturating keeps a shader from turning an
// overflow into inf - inf = NaN); infinities and NaN pass through. Bit operations only, so
// it is exact on every x86-64 and cheap enough to run after every mediump shader op; the
// test checks it against the arithmetic definition.
inline float round_to_fp16(float v) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
  const std::uint32_t sign = bits & 0x80000000u;
  std::uint32_t magnitude = bits & 0x7FFFFFFFu;
  constexpr std::uint32_t kInfinity = 0x7F800000u;
  constexpr std::uint32_t kLargestHalf = 0x477FE000u;     // 65504
  constexpr std::uint32_t kSmallestNormal = 0x38800000u;  // 2^-14
  if (magnitude >= kInfinity) return v;
  if (magnitude >= kLargestHalf) return std::bit_cast<float>(sign | kLargestHalf);
  if (magnitude < kSmallestNormal) {
    // Subnormal half: multiples of 2^-24, the unit in the last place of floats in [0.5, 1),
    // so adding 0.5 rounds to nearest even there and subtracting it is exact.
    const float rounded = (std::bit_cast<float>(magnitude) + 0.5f) - 0.5f;
    return std::bit_cast<float>(sign | std::bit_cast<std::uint32_t>(rounded));
  }
  // Normal half: keep 10 of the float's 23 mantissa bits, ties to even; a carry into the
  // exponent is the correct result.
  magnitude += 0x0FFFu + ((magnitude >> 13) & 1u);
  magnitude &= ~0x1FFFu;
  return std::bit_cast<float>(sign | magnitude);
}

}  // namespace skinsim::sim

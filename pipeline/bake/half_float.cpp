#include "pipeline/bake/half_float.h"

#include <bit>
#include <cmath>

namespace skinsim::bake {

std::uint16_t float_to_half(float value) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  const std::uint16_t sign = static_cast<std::uint16_t>((bits >> 16) & 0x8000u);
  const std::uint32_t magnitude = bits & 0x7FFFFFFFu;
  if (magnitude >= 0x7F800000u) {  // infinity or NaN (keep NaN quiet and non-zero)
    return sign | (magnitude > 0x7F800000u ? 0x7E00u : 0x7C00u);
  }
  // Scale so that the half's unit in the last place becomes 1, then round to nearest even in
  // float arithmetic: the float's 24-bit significand holds every half significand exactly.
  const int exponent = static_cast<int>(magnitude >> 23) - 127;
  const float abs_value = std::bit_cast<float>(magnitude);
  if (exponent < -14) {
    // Subnormal half: units of 2^-24. nearbyint rounds half to even in the default mode.
    return sign | static_cast<std::uint16_t>(std::nearbyint(std::ldexp(abs_value, 24)));
  }
  if (exponent > 15) return sign | 0x7C00u;  // too large: infinity
  // Normal half: significand in units of 2^(exponent - 10); rounding may carry into the
  // exponent, which the bit layout handles (and 65520 and above become infinity).
  const std::uint32_t units =
      static_cast<std::uint32_t>(std::nearbyint(std::ldexp(abs_value, 10 - exponent)));
  const std::uint32_t half = (static_cast<std::uint32_t>(exponent + 15) << 10) + (units - 1024u);
  return sign | static_cast<std::uint16_t>(half >= 0x7C00u ? 0x7C00u : half);
}

float half_to_float(std::uint16_t bits) {
  const float sign = (bits & 0x8000u) != 0 ? -1.0f : 1.0f;
  const int exponent = (bits >> 10) & 0x1F;
  const int mantissa = bits & 0x3FF;
  if (exponent == 0) return sign * std::ldexp(static_cast<float>(mantissa), -24);
  if (exponent == 31) return mantissa == 0 ? sign * INFINITY : NAN;
  return sign * std::ldexp(static_cast<float>(mantissa + 1024), exponent - 25);
}

}  // namespace skinsim::bake

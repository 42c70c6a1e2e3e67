// Colour-space transforms of FLIP (Andersson et al. 2020, section 3 and the reference code
// github.com/NVlabs/flip): sRGB -> linear RGB -> XYZ (D65) -> YCxCz opponent space and back,
// XYZ -> CIELAB, the Hunt adjustment and the HyAB distance.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace skinsim::quality::flip_color {

using dvec3 = glm::dvec3;

inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Linear sRGB primaries to XYZ with the exact rational coefficients of FLIP's code.
inline dvec3 linear_rgb_to_xyz(const dvec3& c) {
  return {(10135552.0 * c.r + 8788810.0 * c.g + 4435075.0 * c.b) / 24577794.0,
          (2613072.0 * c.r + 8788810.0 * c.g + 887015.0 * c.b) / 12288897.0,
          (1425312.0 * c.r + 8788810.0 * c.g + 70074185.0 * c.b) / 73733382.0};
}

inline dvec3 xyz_to_linear_rgb(const dvec3& c) {
  return {3.241003275 * c.x - 1.537398934 * c.y - 0.498615861 * c.z,
          -0.969224334 * c.x + 1.875930071 * c.y + 0.041554224 * c.z,
          0.055639423 * c.x - 0.204011202 * c.y + 1.057148933 * c.z};
}

// The reference white: XYZ of linear RGB (1, 1, 1).
inline dvec3 reference_white() {
  return linear_rgb_to_xyz(dvec3(1.0));
}

// YCxCz (Zhang & Wandell's S-CIELAB opponent space, linear in XYZ).
inline dvec3 xyz_to_ycxcz(const dvec3& xyz) {
  const dvec3 n = xyz / reference_white();
  return {116.0 * n.y - 16.0, 500.0 * (n.x - n.y), 200.0 * (n.y - n.z)};
}

inline dvec3 ycxcz_to_xyz(const dvec3& c) {
  const double y = (c.x + 16.0) / 116.0;
  return dvec3(y + c.y / 500.0, y, y - c.z / 200.0) * reference_white();
}

// Cube root of t in [2^-700, 2^1020] (outside, the steps' y^3 or 2t leave the normal range;
// FLIP's t is in (0.008856, ~1]), within 5 ulp of libm's (about 1e-15 relative,
// tests/quality/metrics_test.cpp): the bit pattern divided by 3 halves and thirds the exponent and
// puts the first guess within 1/32 (Kahan's constant, as fdlibm's cbrt), and each of three Halley
// steps triples the correct bits (5 -> 15 -> 45 -> past 53). A third of glibc 2.36's std::cbrt
// time, which reduces the argument with frexp and ldexp; FLIP takes three per pixel, which made
// std::cbrt (with the frexp and scalbn it calls) 5% of a default sweep's CPU (perf record).
inline double cube_root(double t) {
  double y = std::bit_cast<double>(std::bit_cast<std::uint64_t>(t) / 3 + 0x2A9F789300000000ull);
  for (int step = 0; step < 3; ++step) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * t) / (2.0 * y3 + t);
  }
  return y;
}

inline dvec3 xyz_to_lab(const dvec3& xyz) {
  constexpr double kDelta = 6.0 / 29.0;
  constexpr double kDeltaCube = kDelta * kDelta * kDelta;
  const dvec3 n = xyz / reference_white();
  const auto f = [&](double t) {
    return t > kDeltaCube ? cube_root(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
  };
  const dvec3 fn(f(n.x), f(n.y), f(n.z));
  return {116.0 * fn.y - 16.0, 500.0 * (fn.x - fn.y), 200.0 * (fn.y - fn.z)};
}

// Hunt adjustment (FLIP eq. 2): chroma scales with lightness, a* and b* times 0.01 L*.
inline dvec3 hunt_adjust(const dvec3& lab) {
  return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z};
}

// HyAB distance (Abasi et al. 2020; FLIP eq. 3): city-block in L, Euclidean in (a, b).
inline double hyab(const dvec3& a, const dvec3& b) {
  const double da = a.y - b.y;
  const double db = a.z - b.z;
  return std::abs(a.x - b.x) + std::sqrt(da * da + db * db);
}

// Filtered YCxCz -> linear RGB clamped to [0,1] -> CIELAB -> Hunt-adjusted.
inline dvec3 ycxcz_to_hunt_lab(const dvec3& ycxcz) {
  const dvec3 rgb = glm::clamp(xyz_to_linear_rgb(ycxcz_to_xyz(ycxcz)), dvec3(0.0), dvec3(1.0));
  return hunt_adjust(xyz_to_lab(linear_rgb_to_xyz(rgb)));
}

}  // namespace skinsim::quality::flip_color

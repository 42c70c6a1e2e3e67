// Colour-space transforms of FLIP (Andersson et al. 2020, section 3 and the reference code
// github.com/NVlabs/flip): sRGB -> linear RGB -> XYZ (D65) -> YCxCz opponent space and back,
// XYZ -> CIELAB, the Hunt adjustment and the HyAB distance. In single precision, as NVIDIA's
// C++ and CUDA implementations compute them, on four or eight pixels at once, one per lane
// (util/float_lanes.h).
#pragma once

#include <cmath>

#include "util/float_lanes.h"

// Eight-lane vectors pass only between always-inlined functions (util/float_lanes.h).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace skinsim::quality::flip_color {

// One colour of each of a vector's pixels, one lane each.
template <class V>
struct Colour {
  V x, y, z;
};
using Colour4 = Colour<Float4>;

inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Linear sRGB primaries to XYZ with the exact rational coefficients of FLIP's code (rounded to
// float once, at compile time).
template <class V>
[[gnu::always_inline]] inline Colour<V> linear_rgb_to_xyz(const Colour<V>& c) {
  constexpr float kX[3] = {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0};
  constexpr float kY[3] = {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0};
  constexpr float kZ[3] = {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0};
  return {kX[0] * c.x + kX[1] * c.y + kX[2] * c.z, kY[0] * c.x + kY[1] * c.y + kY[2] * c.z,
          kZ[0] * c.x + kZ[1] * c.y + kZ[2] * c.z};
}

template <class V>
[[gnu::always_inline]] inline Colour<V> xyz_to_linear_rgb(const Colour<V>& c) {
  return {3.241003275f * c.x - 1.537398934f * c.y - 0.498615861f * c.z,
          -0.969224334f * c.x + 1.875930071f * c.y + 0.041554224f * c.z,
          0.055639423f * c.x - 0.204011202f * c.y + 1.057148933f * c.z};
}

// The reference white, XYZ of linear RGB (1, 1, 1): the sums of the rows of
// linear_rgb_to_xyz's matrix, and their reciprocals. Y's is 1 exactly (2613072 + 8788810 +
// 887015 = 12288897).
constexpr float kInverseWhiteX = 24577794.0 / (10135552.0 + 8788810.0 + 4435075.0);
constexpr float kInverseWhiteZ = 73733382.0 / (1425312.0 + 8788810.0 + 70074185.0);
constexpr float kWhiteX = (10135552.0 + 8788810.0 + 4435075.0) / 24577794.0;
constexpr float kWhiteZ = (1425312.0 + 8788810.0 + 70074185.0) / 73733382.0;

// YCxCz (Zhang & Wandell's S-CIELAB opponent space, linear in XYZ).
template <class V>
[[gnu::always_inline]] inline Colour<V> xyz_to_ycxcz(const Colour<V>& xyz) {
  const V nx = xyz.x * kInverseWhiteX, ny = xyz.y;
  const V nz = xyz.z * kInverseWhiteZ;
  return {116.0f * ny - 16.0f, 500.0f * (nx - ny), 200.0f * (ny - nz)};
}

template <class V>
[[gnu::always_inline]] inline Colour<V> ycxcz_to_xyz(const Colour<V>& c) {
  const V y = (c.x + 16.0f) * (1.0f / 116.0f);
  return {(y + c.y * (1.0f / 500.0f)) * kWhiteX, y, (y - c.z * (1.0f / 200.0f)) * kWhiteZ};
}

template <class V>
[[gnu::always_inline]] inline Colour<V> xyz_to_lab(const Colour<V>& xyz) {
  constexpr float kDeltaCube = 6.0 * 6.0 * 6.0 / (29.0 * 29.0 * 29.0);
  constexpr float kToeSlope = 29.0 * 29.0 / (3.0 * 6.0 * 6.0);  // 1 / (3 delta^2)
  const auto f = [&](V t) __attribute__((always_inline)) {
    return t > kDeltaCube ? cbrt_lanes(t) : t * kToeSlope + 4.0f / 29.0f;
  };
  const V fx = f(xyz.x * kInverseWhiteX), fy = f(xyz.y);
  const V fz = f(xyz.z * kInverseWhiteZ);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// Hunt adjustment (FLIP eq. 2): chroma scales with lightness, a* and b* times 0.01 L*.
template <class V>
[[gnu::always_inline]] inline Colour<V> hunt_adjust(const Colour<V>& lab) {
  const V scale = 0.01f * lab.x;
  return {lab.x, scale * lab.y, scale * lab.z};
}

// HyAB distance (Abasi et al. 2020; FLIP eq. 3): city-block in L, Euclidean in (a, b).
template <class V>
[[gnu::always_inline]] inline V hyab(const Colour<V>& a, const Colour<V>& b) {
  const V da = a.y - b.y;
  const V db = a.z - b.z;
  return abs_lanes(a.x - b.x) + sqrt_lanes(da * da + db * db);
}

// Filtered YCxCz -> linear RGB clamped to [0,1] -> CIELAB -> Hunt-adjusted.
template <class V>
[[gnu::always_inline]] inline Colour<V> ycxcz_to_hunt_lab(const Colour<V>& ycxcz) {
  const auto unit = [](V v) __attribute__((always_inline)) {
    return min_lanes(max_lanes(v, splat<V>(0.0f)), splat<V>(1.0f));
  };
  const Colour<V> rgb = xyz_to_linear_rgb(ycxcz_to_xyz(ycxcz));
  return hunt_adjust(
      xyz_to_lab(linear_rgb_to_xyz(Colour<V>{unit(rgb.x), unit(rgb.y), unit(rgb.z)})));
}

}  // namespace skinsim::quality::flip_color

#pragma GCC diagnostic pop

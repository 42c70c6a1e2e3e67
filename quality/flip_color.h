// Colour-space transforms of FLIP (Andersson et al. 2020, section 3 and the reference code
// github.com/NVlabs/flip): sRGB -> linear RGB -> XYZ (D65) -> YCxCz opponent space and back,
// XYZ -> CIELAB, the Hunt adjustment and the HyAB distance. In single precision, as NVIDIA's
// C++ and CUDA implementations compute them, on four pixels at once (quality/float4.h).
#pragma once

#include <cmath>

#include "quality/float4.h"

namespace skinsim::quality::flip_color {

// One colour of each of four pixels, one lane each.
struct Colour4 {
  Float4 x, y, z;
};

inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Linear sRGB primaries to XYZ with the exact rational coefficients of FLIP's code (rounded to
// float once, at compile time).
inline Colour4 linear_rgb_to_xyz(const Colour4& c) {
  constexpr float kX[3] = {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0};
  constexpr float kY[3] = {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0};
  constexpr float kZ[3] = {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0};
  return {kX[0] * c.x + kX[1] * c.y + kX[2] * c.z, kY[0] * c.x + kY[1] * c.y + kY[2] * c.z,
          kZ[0] * c.x + kZ[1] * c.y + kZ[2] * c.z};
}

inline Colour4 xyz_to_linear_rgb(const Colour4& c) {
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
inline Colour4 xyz_to_ycxcz(const Colour4& xyz) {
  const Float4 nx = xyz.x * kInverseWhiteX, ny = xyz.y;
  const Float4 nz = xyz.z * kInverseWhiteZ;
  return {116.0f * ny - 16.0f, 500.0f * (nx - ny), 200.0f * (ny - nz)};
}

inline Colour4 ycxcz_to_xyz(const Colour4& c) {
  const Float4 y = (c.x + 16.0f) * (1.0f / 116.0f);
  return {(y + c.y * (1.0f / 500.0f)) * kWhiteX, y, (y - c.z * (1.0f / 200.0f)) * kWhiteZ};
}

inline Colour4 xyz_to_lab(const Colour4& xyz) {
  constexpr float kDeltaCube = 6.0 * 6.0 * 6.0 / (29.0 * 29.0 * 29.0);
  constexpr float kToeSlope = 29.0 * 29.0 / (3.0 * 6.0 * 6.0);  // 1 / (3 delta^2)
  const auto f = [&](Float4 t) { return t > kDeltaCube ? cbrt4(t) : t * kToeSlope + 4.0f / 29.0f; };
  const Float4 fx = f(xyz.x * kInverseWhiteX), fy = f(xyz.y);
  const Float4 fz = f(xyz.z * kInverseWhiteZ);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// Hunt adjustment (FLIP eq. 2): chroma scales with lightness, a* and b* times 0.01 L*.
inline Colour4 hunt_adjust(const Colour4& lab) {
  const Float4 scale = 0.01f * lab.x;
  return {lab.x, scale * lab.y, scale * lab.z};
}

// HyAB distance (Abasi et al. 2020; FLIP eq. 3): city-block in L, Euclidean in (a, b).
inline Float4 hyab(const Colour4& a, const Colour4& b) {
  const Float4 da = a.y - b.y;
  const Float4 db = a.z - b.z;
  return abs4(a.x - b.x) + sqrt4(da * da + db * db);
}

// Filtered YCxCz -> linear RGB clamped to [0,1] -> CIELAB -> Hunt-adjusted.
inline Colour4 ycxcz_to_hunt_lab(const Colour4& ycxcz) {
  const auto unit = [](Float4 v) { return min4(max4(v, splat(0.0f)), splat(1.0f)); };
  const Colour4 rgb = xyz_to_linear_rgb(ycxcz_to_xyz(ycxcz));
  return hunt_adjust(xyz_to_lab(linear_rgb_to_xyz({unit(rgb.x), unit(rgb.y), unit(rgb.z)})));
}

}  // namespace skinsim::quality::flip_color

// Screen-space triangle set-up produced by the geometry stage and consumed by the per-tile
// rasteriser: fixed-point edge equations, and plane equations for depth, 1/w and each
// varying divided by w (all linear in screen space, which makes interpolation perspective
// correct).
#pragma once

#include <cstdint>

namespace skinsim::sim {

// Sub-pixel precision of the rasteriser: 8 bits, as in common GPU rasterisers.
constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixelOne = std::int64_t{1} << kSubpixelBits;

// value(x, y) = c + dx * (x - origin_x) + dy * (y - origin_y), x/y in pixels.
struct Plane {
  float c = 0.0f;
  float dx = 0.0f;
  float dy = 0.0f;
  float at(float rx, float ry) const { return c + dx * rx + dy * ry; }
};

struct TriangleSetup {
  // Edge i: E(x, y) = a*x + b*y + c, x/y = pixel-centre positions in sub-pixel units. A
  // pixel is covered when every E > 0, or E == 0 on a top-left edge (D3D10/GL fill rule);
  // the rule's -1 bias on other edges is folded into c, so the test is E >= 0 throughout.
  std::int64_t edge_a[3];
  std::int64_t edge_b[3];
  std::int64_t edge_c[3];
  // Pixel bounding box, inclusive, clamped to the render area.
  int min_x, min_y, max_x, max_y;
  float origin_x, origin_y;      // pixel-space origin of the planes
  Plane depth;                   // z/w in [0,1]
  Plane inv_w;                   // 1/w
  std::uint32_t varying_offset;  // first plane in the pass's varying-plane pool
  std::uint32_t draw;            // index of the draw call it came from
};

}  // namespace skinsim::sim

// The tiler's front half (TA): vertex shading, clipping, culling and triangle set-up for
// one render pass, in submission order.
#pragma once

#include <vector>

#include "sim/counters.h"
#include "sim/render_pass.h"
#include "sim/triangle_setup.h"

namespace skinsim::sim {

struct SetupTriangles {
  std::vector<TriangleSetup> triangles;  // submission order
  std::vector<Plane> varying_planes;     // pool indexed by TriangleSetup::varying_offset
};

// Pixel-space area the pass renders: the render area snapped outward to whole tiles and
// clipped to the target.
PixelRect tile_aligned_area(const RenderPassDesc& pass, int tile_size);

SetupTriangles run_geometry(const RenderPassDesc& pass, const PixelRect& area,
                            PassCounters& counters);

}  // namespace skinsim::sim

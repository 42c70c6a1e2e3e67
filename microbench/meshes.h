// Geometry of the micro-benchmark passes: regular grids in clip space.
#pragma once

#include "sim/mesh.h"

namespace skinsim::microbench {

using sim::Mesh;

enum class Winding { kCounterClockwise, kClockwise };

// cells_x x cells_y cells over clip-space [-1,1]^2 at depth z, two triangles per cell,
// shared vertices, uv in [0,1]^2. Counter-clockwise triangles are front faces (OpenGL).
Mesh grid_mesh(int cells_x, int cells_y, float z, Winding winding = Winding::kCounterClockwise);

}  // namespace skinsim::microbench

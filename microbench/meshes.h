// Geometry of the micro-benchmark passes: regular grids in clip space.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "sim/render_pass.h"

namespace skinsim::microbench {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;

  std::size_t triangle_count() const { return indices.size() / 3; }
  // Views into this mesh: it must outlive the draw that uses them.
  sim::Geometry geometry() const;
};

enum class Winding { kCounterClockwise, kClockwise };

// cells_x x cells_y cells over clip-space [-1,1]^2 at depth z, two triangles per cell,
// shared vertices, uv in [0,1]^2. Counter-clockwise triangles are front faces (OpenGL).
Mesh grid_mesh(int cells_x, int cells_y, float z, Winding winding = Winding::kCounterClockwise);

}  // namespace skinsim::microbench

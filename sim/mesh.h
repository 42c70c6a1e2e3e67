// Triangles held in vectors (positions, uvs, indices), and the Geometry a draw reads from
// them: what the screen quads, the micro-benchmarks' grids and the emulator's tests draw.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "sim/render_pass.h"

namespace skinsim::sim {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> uvs;  // empty: none (the vertex stage reads (0, 0))
  std::vector<std::uint32_t> indices;

  std::size_t triangle_count() const { return indices.size() / 3; }
  // Views into this mesh: it must outlive the draw that uses them.
  Geometry geometry() const {
    Geometry g;
    g.attributes.positions = positions.data();
    g.attributes.uvs = uvs.empty() ? nullptr : uvs.data();
    g.vertex_count = positions.size();
    g.indices = indices.data();
    g.index_count = indices.size();
    return g;
  }
};

}  // namespace skinsim::sim

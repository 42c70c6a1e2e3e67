#include "microbench/meshes.h"

namespace skinsim::microbench {

Mesh grid_mesh(int cells_x, int cells_y, float z, Winding winding) {
  Mesh m;
  const auto columns = static_cast<std::size_t>(cells_x) + 1;
  m.positions.reserve(columns * (static_cast<std::size_t>(cells_y) + 1));
  m.uvs.reserve(m.positions.capacity());
  for (int j = 0; j <= cells_y; ++j) {
    for (int i = 0; i <= cells_x; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(cells_x);
      const float v = static_cast<float>(j) / static_cast<float>(cells_y);
      m.positions.emplace_back(2.0f * u - 1.0f, 2.0f * v - 1.0f, z);
      m.uvs.emplace_back(u, v);
    }
  }
  m.indices.reserve(static_cast<std::size_t>(cells_x) * cells_y * 6);
  for (int j = 0; j < cells_y; ++j) {
    for (int i = 0; i < cells_x; ++i) {
      const auto a = static_cast<std::uint32_t>(j * columns + i);
      const std::uint32_t b = a + 1;
      const auto c = static_cast<std::uint32_t>(a + columns);
      const std::uint32_t d = c + 1;
      if (winding == Winding::kCounterClockwise) {
        m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
      } else {
        m.indices.insert(m.indices.end(), {a, d, b, a, c, d});
      }
    }
  }
  return m;
}

}  // namespace skinsim::microbench

#include "scene/head_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/head_shape.h"
#include "scene/mesh_attributes.h"

namespace skinsim::scene::head {
namespace {

void finish(Mesh& m) {
  m.normals = compute_smooth_normals(m.positions, m.indices);
  m.tangents = compute_tangents(m.positions, m.normals, m.uvs, m.indices);
}

// Two counter-clockwise (seen from outside) triangles for a grid cell whose corners are
// a = (row, col), b = (row + 1, col), c = (row, col + 1), d = (row + 1, col + 1), when
// columns run to the right and rows run down the outside of the surface.
void add_cell(std::vector<std::uint32_t>& idx, std::uint32_t a, std::uint32_t b, std::uint32_t c,
              std::uint32_t d) {
  idx.insert(idx.end(), {a, b, c, c, b, d});
}

}  // namespace

Mesh make_head_mesh(int target_triangles) {
  // The grid gives 2 * columns * rows triangles (crown fan + cells + neck cap). Rows of
  // about 0.6 x columns keep the quads roughly square on the head; among nearby column
  // counts take the one whose total comes closest to the target.
  const int guess = static_cast<int>(std::lround(std::sqrt(target_triangles / 1.2)));
  int columns = 0, rows = 0;
  for (int c = std::max(8, guess - 6); c <= guess + 6; ++c) {
    const int r = std::max(4, static_cast<int>(std::lround(target_triangles / (2.0 * c))));
    if (columns == 0 ||
        std::abs(2 * c * r - target_triangles) < std::abs(2 * columns * rows - target_triangles)) {
      columns = c;
      rows = r;
    }
  }
  Mesh m;
  m.name = "head";
  const int stride = columns + 1;  // the seam column is duplicated
  for (int r = 0; r <= rows; ++r) {
    const float v = static_cast<float>(r) / rows;
    for (int c = 0; c <= columns; ++c) {
      // Row 0 is the crown pole: give each copy the u of the middle of its fan triangle.
      const float u = (c + (r == 0 ? 0.5f : 0.0f)) / columns;
      // The seam column repeats column 0's position exactly (u = 1 would round differently).
      m.positions.push_back(surface_point(c == columns ? 0.0f : u, v));
      m.uvs.emplace_back(u, v);
    }
  }
  const auto at = [&](int r, int c) { return static_cast<std::uint32_t>(r * stride + c); };
  for (int c = 0; c < columns; ++c) {  // crown fan
    m.indices.insert(m.indices.end(), {at(0, c), at(1, c), at(1, c + 1)});
  }
  for (int r = 1; r < rows; ++r) {
    for (int c = 0; c < columns; ++c)
      add_cell(m.indices, at(r, c), at(r + 1, c), at(r, c + 1), at(r + 1, c + 1));
  }
  // Cap under the neck: one centre vertex per column (its own u), facing down.
  const std::uint32_t cap0 = static_cast<std::uint32_t>(m.positions.size());
  for (int c = 0; c < columns; ++c) {
    m.positions.emplace_back(0.0f, neck_bottom_y(), neck_center_z());
    m.uvs.emplace_back((c + 0.5f) / columns, 1.0f);
    m.indices.insert(m.indices.end(), {at(rows, c), cap0 + c, at(rows, c + 1)});
  }
  finish(m);
  return m;
}

Mesh make_ellipsoid(const std::string& name, const glm::vec3& center, const glm::vec3& radii,
                    int slices, int stacks) {
  constexpr float kPi = std::numbers::pi_v<float>;
  Mesh m;
  m.name = name;
  const int stride = slices + 1;
  for (int s = 0; s <= stacks; ++s) {
    const float v = static_cast<float>(s) / stacks;
    const float theta = v * kPi;  // from the +Z pole
    // Exact poles and seam, so coincident vertices are bit-identical and weld.
    const float sin_t = s == 0 || s == stacks ? 0.0f : std::sin(theta);
    const float cos_t = s == 0 ? 1.0f : s == stacks ? -1.0f : std::cos(theta);
    for (int c = 0; c <= slices; ++c) {
      const float u = static_cast<float>(c) / slices;
      // Azimuth runs clockwise seen from +Z: from +X towards -Y as u grows.
      const float phi = 2.0f * kPi * static_cast<float>(c % slices) / slices;
      const glm::vec3 d(sin_t * std::cos(phi), -sin_t * std::sin(phi), cos_t);
      m.positions.push_back(center + d * radii);
      m.uvs.emplace_back(u, v);
    }
  }
  const auto at = [&](int s, int c) { return static_cast<std::uint32_t>(s * stride + c); };
  for (int s = 0; s < stacks; ++s) {
    for (int c = 0; c < slices; ++c) {
      // Rows run from the +Z pole outwards; columns turn clockwise seen from +Z.
      const std::uint32_t a = at(s, c), b = at(s + 1, c), cc = at(s, c + 1), d = at(s + 1, c + 1);
      if (s > 0) m.indices.insert(m.indices.end(), {a, cc, b});
      if (s + 1 < stacks) m.indices.insert(m.indices.end(), {cc, d, b});
    }
  }
  finish(m);
  return m;
}

Mesh make_wall(const std::string& name, float z, float x0, float x1, float y0, float y1) {
  Mesh m;
  m.name = name;
  m.positions = {{x0, y1, z}, {x1, y1, z}, {x0, y0, z}, {x1, y0, z}};
  m.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}};
  m.indices = {0, 2, 1, 1, 2, 3};
  finish(m);
  return m;
}

}  // namespace skinsim::scene::head

#include "pipeline/reference/shadow_origin.h"

#include <algorithm>
#include <cstddef>

namespace skinsim::pipeline::reference {

glm::vec3 smooth_surface_point(const std::array<glm::vec3, 3>& corners,
                               const std::array<glm::vec3, 3>& normals,
                               const glm::vec3& barycentric) {
  const glm::vec3 p =
      barycentric.x * corners[0] + barycentric.y * corners[1] + barycentric.z * corners[2];
  glm::vec3 lifted(0.0f);
  for (int i = 0; i < 3; ++i) {
    // p projected onto corner i's tangent plane where it lies below the plane.
    const float below = std::min(0.0f, glm::dot(p - corners[i], normals[i]));
    lifted += barycentric[i] * (p - below * normals[i]);
  }
  return lifted;
}

glm::vec3 shadow_ray_origin(const GpuScene& gs, const glm::vec3& eye, const glm::vec3& p,
                            float slack) {
  const glm::vec3 view = glm::normalize(p - eye);
  const auto hit = gs.rays().nearest_triangle(p - slack * view, view, 0.0f, 2.0f * slack);
  if (!hit) return p;
  const scene::Mesh& mesh = gs.scene().meshes[hit->mesh];
  if (mesh.normals.empty()) return p;
  std::array<glm::vec3, 3> corners, normals;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::uint32_t v = mesh.indices[3 * static_cast<std::size_t>(hit->triangle) + i];
    corners[i] = mesh.positions[v];
    normals[i] = mesh.normals[v];
  }
  return smooth_surface_point(corners, normals, hit->barycentric);
}

}  // namespace skinsim::pipeline::reference

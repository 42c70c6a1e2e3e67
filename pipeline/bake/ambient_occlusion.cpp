#include "pipeline/bake/ambient_occlusion.h"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>

namespace skinsim::bake {

namespace {

constexpr int kRays = 32;

// Cosine-distributed directions around +z (z = sqrt(1 - u) on a Fibonacci spiral), so the
// unoccluded fraction is the cosine-weighted visibility.
std::array<glm::vec3, kRays> cosine_directions() {
  std::array<glm::vec3, kRays> d{};
  const float golden = 2.39996323f;  // pi (3 - sqrt 5)
  for (int i = 0; i < kRays; ++i) {
    const float u = (static_cast<float>(i) + 0.5f) / kRays;
    const float z = std::sqrt(1.0f - u);
    const float r = std::sqrt(u);
    const float phi = golden * static_cast<float>(i);
    d[i] = {r * std::cos(phi), r * std::sin(phi), z};
  }
  return d;
}

}  // namespace

float ambient_occlusion_at(const RayScene& rays, const glm::vec3& p, const glm::vec3& n,
                           float units_per_mm) {
  static const std::array<glm::vec3, kRays> kHemisphere = cosine_directions();
  if (!(glm::dot(n, n) > 0.5f)) return 1.0f;
  const float reach = kAoReachMm * units_per_mm;
  const float start = 0.01f * units_per_mm;  // 10 um: past the point's own triangles
  const glm::vec3 axis = glm::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 x = glm::normalize(glm::cross(axis, n));
  const glm::vec3 y = glm::cross(n, x);
  std::array<glm::vec3, kRays> directions;
  for (int i = 0; i < kRays; ++i) {
    const glm::vec3& c = kHemisphere[i];
    directions[i] = x * c.x + y * c.y + n * c.z;
  }
  return static_cast<float>(rays.unoccluded(p, directions, start, reach)) / kRays;
}

std::vector<float> bake_ambient_occlusion(const RayScene& rays,
                                          const std::vector<glm::vec3>& positions,
                                          const std::vector<glm::vec3>& normals,
                                          float units_per_mm) {
  std::vector<float> ao(positions.size(), 1.0f);
  if (normals.size() != positions.size()) return ao;
  tbb::parallel_for(std::size_t{0}, positions.size(), [&](std::size_t v) {
    ao[v] = ambient_occlusion_at(rays, positions[v], normals[v], units_per_mm);
  });
  return ao;
}

}  // namespace skinsim::bake

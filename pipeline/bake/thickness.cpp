#include "pipeline/bake/thickness.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace skinsim::bake {

namespace {

constexpr int kConeRays = 16;
constexpr float kConeHalfAngle = 0.5f;  // radians: ~30 degrees around -N

// Directions in the local frame (z = into the mesh): a Fibonacci spiral over the cone.
std::array<glm::vec3, kConeRays> cone_directions() {
  std::array<glm::vec3, kConeRays> d{};
  const float golden = 2.39996323f;  // pi (3 - sqrt 5)
  const float cos_max = std::cos(kConeHalfAngle);
  for (int i = 0; i < kConeRays; ++i) {
    const float z = 1.0f - (1.0f - cos_max) * (static_cast<float>(i) + 0.5f) / kConeRays;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = golden * static_cast<float>(i);
    d[i] = {r * std::cos(phi), r * std::sin(phi), z};
  }
  return d;
}

}  // namespace

float thickness_at_mm(const RayScene& rays, const glm::vec3& p, const glm::vec3& n,
                      float units_per_mm) {
  static const std::array<glm::vec3, kConeRays> kCone = cone_directions();
  if (!(glm::dot(n, n) > 0.5f)) return kMaxThicknessMm;
  const float max_units = kMaxThicknessMm * units_per_mm;
  const float start = 0.01f * units_per_mm;  // 10 um: past the point's own triangles
  const glm::vec3 in = -n;
  const glm::vec3 helper = std::abs(in.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, in));
  const glm::vec3 b = glm::cross(in, t);
  float sum = 0.0f;
  for (const glm::vec3& c : kCone) {
    const glm::vec3 dir = t * c.x + b * c.y + in * c.z;
    sum += std::min(rays.closest_hit(p, dir, start, max_units), max_units);
  }
  return sum / kConeRays / units_per_mm;
}

std::vector<float> bake_thickness_mm(const RayScene& rays, const std::vector<glm::vec3>& positions,
                                     const std::vector<glm::vec3>& normals, float units_per_mm) {
  std::vector<float> thickness(positions.size(), kMaxThicknessMm);
  if (normals.size() != positions.size()) return thickness;
  tbb::parallel_for(std::size_t{0}, positions.size(), [&](std::size_t v) {
    thickness[v] = thickness_at_mm(rays, positions[v], normals[v], units_per_mm);
  });
  return thickness;
}

}  // namespace skinsim::bake

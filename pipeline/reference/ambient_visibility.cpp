#include "pipeline/reference/ambient_visibility.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "pipeline/reference/pixel_noise.h"

namespace skinsim::pipeline::reference {

namespace {

// The character's meshes: what hides the ambient (the header says why not the others).
std::vector<bake::RayMesh> character_meshes(const GpuScene& gs) {
  std::vector<bake::RayMesh> out;
  for (const GpuMesh& m : gs.meshes()) {
    if (gs.materials()[m.material].kind == scene::MaterialKind::kOther) continue;
    out.push_back({&m.mesh->positions, &m.mesh->indices});
  }
  return out;
}

}  // namespace

glm::vec3 sample_cube(const sim::TextureCube& cube, const glm::vec3& direction) {
  const sim::CubeCoord c = sim::cube_coord(direction);
  const sim::LevelView& l = cube.face(c.face).level(0);
  const float fx = std::clamp(c.uv.x * l.width - 0.5f, 0.0f, l.width - 1.0f);
  const float fy = std::clamp(c.uv.y * l.height - 0.5f, 0.0f, l.height - 1.0f);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const int x1 = std::min(x0 + 1, l.width - 1), y1 = std::min(y0 + 1, l.height - 1);
  const float ax = fx - x0, ay = fy - y0;
  const glm::vec4 top = glm::mix(l.at(x0, y0), l.at(x1, y0), ax);
  const glm::vec4 bottom = glm::mix(l.at(x0, y1), l.at(x1, y1), ax);
  return glm::vec3(glm::mix(top, bottom, ay));
}

AmbientRays::AmbientRays(const GpuScene& gs)
    : occluders_(character_meshes(gs)), environment_(gs.environment()) {}

AmbientVisibility AmbientRays::at(const glm::vec3& origin, const glm::vec3& n, int x, int y,
                                  float t_near) const {
  const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, n));
  const glm::vec3 b = glm::cross(n, t);
  // Point i of the Fibonacci lattice, (i / kRays, i / golden ratio) mod 1, shifted by the
  // pixel's two noise values (streams 1 and 2: the shadow rays' rotation is stream 0).
  const float shift_u = interleaved_gradient_noise(x, y, 1);
  const float shift_v = interleaved_gradient_noise(x, y, 2);
  std::array<glm::vec3, kRays> directions;
  for (int i = 0; i < kRays; ++i) {
    const float u = std::fmod(static_cast<float>(i) / kRays + shift_u, 1.0f);
    const float v = std::fmod(0.618033989f * static_cast<float>(i) + shift_v, 1.0f);
    // Malley's method: a uniform point on the unit disc, lifted onto the hemisphere.
    const float r = std::sqrt(u), phi = 6.2831853f * v;
    const float z = std::sqrt(std::max(0.0f, 1.0f - u));
    directions[i] = glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + z * n);
  }
  std::array<bool, kRays> open;
  const int open_count = occluders_.unoccluded(origin, directions, t_near,
                                               std::numeric_limits<float>::infinity(), open);
  AmbientVisibility out;
  out.ambient = static_cast<float>(open_count) / kRays;
  if (open_count == kRays) return out;
  glm::vec3 all(0.0f), seen(0.0f);
  for (int i = 0; i < kRays; ++i) {
    const glm::vec3 radiance = sample_cube(environment_, directions[i]);
    all += radiance;
    if (open[i]) seen += radiance;
  }
  for (int c = 0; c < 3; ++c) out.environment[c] = all[c] > 0.0f ? seen[c] / all[c] : out.ambient;
  return out;
}

}  // namespace skinsim::pipeline::reference

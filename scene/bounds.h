// Axis-aligned bounding boxes of meshes and scenes (world space).
#pragma once

#include <glm/glm.hpp>
#include <limits>

#include "scene/scene.h"

namespace skinsim::scene {

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  glm::vec3 extent() const { return max - min; }
  void grow(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void grow(const Bounds& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
};

// Bounds of the vertices referenced by the mesh's indices (unreferenced vertices ignored).
Bounds mesh_bounds(const Mesh& mesh);
Bounds scene_bounds(const Scene& scene);

}  // namespace skinsim::scene

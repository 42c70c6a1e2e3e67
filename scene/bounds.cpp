#include "scene/bounds.h"

namespace skinsim::scene {

Bounds mesh_bounds(const Mesh& mesh) {
  Bounds b;
  for (std::uint32_t i : mesh.indices) b.grow(mesh.positions[i]);
  return b;
}

Bounds scene_bounds(const Scene& scene) {
  Bounds b;
  for (const Mesh& m : scene.meshes) b.grow(mesh_bounds(m));
  return b;
}

}  // namespace skinsim::scene

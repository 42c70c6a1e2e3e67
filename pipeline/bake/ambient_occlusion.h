// Per-vertex ambient occlusion for the urp technique's baked AO term (offline, as an artist's
// AO map): the cosine-weighted fraction of the hemisphere around N whose rays leave the mesh
// within kAoReachMm (the scale of eye sockets, nostrils and the lips' crease).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "pipeline/bake/ray_scene.h"

namespace skinsim::bake {

inline constexpr float kAoReachMm = 40.0f;

// The ambient occlusion at one surface point with unit normal n: 1 open, 0 closed.
float ambient_occlusion_at(const RayScene& rays, const glm::vec3& p, const glm::vec3& n,
                           float units_per_mm);

std::vector<float> bake_ambient_occlusion(const RayScene& rays,
                                          const std::vector<glm::vec3>& positions,
                                          const std::vector<glm::vec3>& normals,
                                          float units_per_mm);

}  // namespace skinsim::bake

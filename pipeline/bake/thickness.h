// Per-vertex thickness for transmission (offline, as HDRP's thickness maps): the mean distance
// through the mesh from each vertex, inwards, over a cone of rays around -N (an "inverted
// ambient occlusion" bake). Rays that leave the mesh count as kMaxThicknessMm.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "pipeline/bake/ray_scene.h"

namespace skinsim::bake {

inline constexpr float kMaxThicknessMm = 50.0f;  // beyond ~20 mm skin transmits nothing

// The thickness at one surface point with unit normal n (mm, at most kMaxThicknessMm).
float thickness_at_mm(const RayScene& rays, const glm::vec3& p, const glm::vec3& n,
                      float units_per_mm);

std::vector<float> bake_thickness_mm(const RayScene& rays, const std::vector<glm::vec3>& positions,
                                     const std::vector<glm::vec3>& normals, float units_per_mm);

}  // namespace skinsim::bake

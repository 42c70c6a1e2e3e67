// A tiling pore-scale normal map for the urp technique's detail normals, generated because
// neither built-in scene carries a detail map: a height field of pores (one Gaussian dimple
// per cell of a grid, jittered by an integer hash, so the result is deterministic) whose
// slopes give tangent-space normals. It tiles: pores near an edge wrap to the opposite one.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace skinsim::bake {

struct PoreNormalParams {
  int size = 128;          // texels per axis (a power of two: the map is mipmapped)
  int cells = 16;          // pores per axis
  float radius = 1.2f;     // pore standard deviation, texels
  float depth = 1.0f;      // pore depth, texels of height
  std::uint32_t seed = 1;  // the jitter's hash seed
};

// size x size unit tangent-space normals, row-major (z up, out of the surface).
std::vector<glm::vec3> bake_pore_normals(const PoreNormalParams& params);

}  // namespace skinsim::bake

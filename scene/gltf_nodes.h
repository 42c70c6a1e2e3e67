// Flattens a glTF scene's node tree into world transforms (internal to the glTF loader).
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace skinsim::scene {
struct NodeAnimation;
}

namespace skinsim::scene::gltf {

struct PlacedNode {
  int node = -1;
  glm::mat4 world{1.0f};
  // Its mesh's morph weights (spec 3.7.2.2): the animation's, else the node's, else the mesh's
  // defaults, else zeros; one per morph target (none without a mesh or targets).
  std::vector<float> weights;
};

// Most nodes a file may have. Each node with a mesh becomes a separate draw with fixed
// per-draw set-up cost in the pipeline, so 100,000 one-triangle nodes ran for minutes;
// head scans have a handful of nodes.
inline constexpr std::size_t kMaxNodes = 4096;

// Nodes of scenes[scene_index] in depth-first pre-order (document order), each with its
// world matrix. The glTF spec (3.5.3) requires the nodes to form disjoint trees: a node
// reached twice (a cycle or a second parent) throws SceneError, as do out-of-range
// indices, malformed TRS/matrix values and more than kMaxNodes nodes. Iterative, so deep trees
// cannot overflow the stack. With `animation`, the nodes it moves take their transform at
// `time_s` (gltf_animation.h); such a node must use TRS, not a matrix (spec 3.11). Weights
// that do not match the mesh's morph targets in number throw SceneError naming the field.
std::vector<PlacedNode> flatten_scene(const tinygltf::Model& model, int scene_index,
                                      const std::string& file,
                                      const NodeAnimation* animation = nullptr,
                                      double time_s = 0.0);

}  // namespace skinsim::scene::gltf

// Flattens a glTF scene's node tree into world transforms (internal to the glTF loader).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace skinsim::scene::gltf {

struct PlacedNode {
  int node = -1;
  glm::mat4 world{1.0f};
};

// Nodes of scenes[scene_index] in depth-first pre-order (document order), each with its
// world matrix. The glTF spec (3.5.3) requires the nodes to form disjoint trees: a node
// reached twice (a cycle or a second parent) throws SceneError, as do out-of-range
// indices and malformed TRS/matrix values. Iterative, so deep trees cannot overflow the stack.
std::vector<PlacedNode> flatten_scene(const tinygltf::Model& model, int scene_index,
                                      const std::string& file);

}  // namespace skinsim::scene::gltf

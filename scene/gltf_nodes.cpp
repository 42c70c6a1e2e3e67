#include "scene/gltf_nodes.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/error.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_primitive.h"

namespace skinsim::scene::gltf {
namespace {

void check_numbers(const std::vector<double>& v, std::size_t expected, const char* field, int node,
                   const std::string& file) {
  if (v.empty()) return;
  if (v.size() != expected) {
    throw SceneError(fmt::format("{}: nodes[{}].{} must have {} numbers, has {}", file, node, field,
                                 expected, v.size()));
  }
  for (double x : v) {
    if (!std::isfinite(x)) {
      throw SceneError(fmt::format("{}: nodes[{}].{} is not finite", file, node, field));
    }
  }
}

// glTF 2.0 spec 3.5.2: either a column-major matrix or T * R * S.
glm::mat4 local_matrix(const tinygltf::Node& n, int index, const std::string& file) {
  check_numbers(n.matrix, 16, "matrix", index, file);
  check_numbers(n.translation, 3, "translation", index, file);
  check_numbers(n.rotation, 4, "rotation", index, file);
  check_numbers(n.scale, 3, "scale", index, file);
  if (!n.matrix.empty()) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(n.matrix[i]);
    return m;
  }
  glm::mat4 m(1.0f);
  if (!n.translation.empty()) {
    m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
  }
  if (!n.rotation.empty()) {
    glm::quat q(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
    const float len = glm::length(q);
    if (!(len > 0.0f)) {
      throw SceneError(fmt::format("{}: nodes[{}].rotation is a zero quaternion", file, index));
    }
    m *= glm::mat4_cast(q / len);
  }
  if (!n.scale.empty()) m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
  return m;
}

// An animated node's transform at `time_s`: its own TRS with the animation's channels applied.
glm::mat4 animated_matrix(const tinygltf::Node& n, int index, const NodeAnimation& animation,
                          double time_s, const std::string& file) {
  if (!n.matrix.empty()) {
    throw SceneError(fmt::format(
        "{}: nodes[{}].matrix: an animated node must use translation, rotation and scale", file,
        index));
  }
  local_matrix(n, index, file);  // checks its TRS values
  NodeTrs rest;
  if (!n.translation.empty()) rest.translation = glm::vec3(glm::make_vec3(n.translation.data()));
  if (!n.rotation.empty()) {
    rest.rotation = glm::normalize(
        glm::quat(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                  static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2])));
  }
  if (!n.scale.empty()) rest.scale = glm::vec3(glm::make_vec3(n.scale.data()));
  return sample_node(animation, index, time_s, rest).matrix();
}

// PlacedNode::weights for node `index`.
std::vector<float> node_weights(const tinygltf::Model& model, int index,
                                const NodeAnimation* animation, double time_s,
                                const std::string& file) {
  const tinygltf::Node& n = model.nodes[static_cast<std::size_t>(index)];
  // A mesh index out of range is the loader's to report (gltf_loader.cpp).
  const bool has_mesh = n.mesh >= 0 && static_cast<std::size_t>(n.mesh) < model.meshes.size();
  const std::size_t targets = has_mesh ? morph_target_count(model, n.mesh, file) : 0;
  const auto given = [&](const std::vector<double>& weights, const std::string& field) {
    if (weights.size() != targets) {
      throw SceneError(fmt::format("{}: {}: {} weights for {} morph targets{}", file, field,
                                   weights.size(), targets,
                                   has_mesh ? fmt::format(" (meshes[{}])", n.mesh) : ""));
    }
    return std::vector<float>(weights.begin(), weights.end());
  };
  std::vector<float> weights(targets, 0.0f);
  if (has_mesh && !model.meshes[static_cast<std::size_t>(n.mesh)].weights.empty()) {
    weights = given(model.meshes[static_cast<std::size_t>(n.mesh)].weights,
                    fmt::format("meshes[{}].weights", n.mesh));
  }
  if (!n.weights.empty()) weights = given(n.weights, fmt::format("nodes[{}].weights", index));
  return animation ? sample_weights(*animation, index, time_s, std::move(weights)) : weights;
}

int checked_node(const tinygltf::Model& model, int node, const std::string& where,
                 const std::string& file) {
  if (node < 0 || static_cast<std::size_t>(node) >= model.nodes.size()) {
    throw SceneError(fmt::format("{}: {}: node index {} out of range ({} nodes)", file, where, node,
                                 model.nodes.size()));
  }
  return node;
}

}  // namespace

std::vector<PlacedNode> flatten_scene(const tinygltf::Model& model, int scene_index,
                                      const std::string& file, const NodeAnimation* animation,
                                      double time_s) {
  if (model.nodes.size() > kMaxNodes) {
    throw SceneError(
        fmt::format("{}: {} nodes; skinsim reads at most {}", file, model.nodes.size(), kMaxNodes));
  }
  enum State : unsigned char { kUnseen, kOnPath, kDone };
  std::vector<State> state(model.nodes.size(), kUnseen);
  struct Frame {
    int node;
    glm::mat4 world;
    std::size_t next_child;
  };
  std::vector<Frame> stack;
  std::vector<PlacedNode> out;

  auto enter = [&](int node, const glm::mat4& parent, const std::string& where) {
    if (state[node] == kOnPath) {
      throw SceneError(fmt::format("{}: {}: node {} is its own ancestor (cycle in the node graph)",
                                   file, where, node));
    }
    if (state[node] == kDone) {
      throw SceneError(
          fmt::format("{}: {}: node {} is reached twice (it has two parents)", file, where, node));
    }
    state[node] = kOnPath;
    const glm::mat4 world =
        parent * (animation && animation->moves(node)
                      ? animated_matrix(model.nodes[node], node, *animation, time_s, file)
                      : local_matrix(model.nodes[node], node, file));
    out.push_back({node, world, node_weights(model, node, animation, time_s, file)});
    stack.push_back({node, world, 0});
  };

  const auto& roots = model.scenes[static_cast<std::size_t>(scene_index)].nodes;
  for (std::size_t r = 0; r < roots.size(); ++r) {
    const std::string where = fmt::format("scenes[{}].nodes[{}]", scene_index, r);
    enter(checked_node(model, roots[r], where, file), glm::mat4(1.0f), where);
    while (!stack.empty()) {
      Frame& top = stack.back();
      const auto& children = model.nodes[static_cast<std::size_t>(top.node)].children;
      if (top.next_child == children.size()) {
        state[top.node] = kDone;
        stack.pop_back();
        continue;
      }
      const std::string child_where =
          fmt::format("nodes[{}].children[{}]", top.node, top.next_child);
      const int child = checked_node(model, children[top.next_child++], child_where, file);
      const glm::mat4 parent_world = top.world;  // `top` dies when enter() pushes
      enter(child, parent_world, child_where);
    }
  }
  return out;
}

}  // namespace skinsim::scene::gltf

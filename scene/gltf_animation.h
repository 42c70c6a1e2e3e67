// A glTF animation (glTF 2.0 spec, 3.11 "Animations"): each channel moves one node's
// translation, rotation, scale or morph-target weights (one per target of the node's mesh,
// spec 3.7.2.2) along keyframes with LINEAR (rotation: spherical linear), STEP or CUBICSPLINE
// (Hermite, with the in- and out-tangents stored around each value) interpolation. Before the
// first keyframe a channel holds its first value, after the last its last.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace skinsim::scene {

enum class AnimationPath { kTranslation, kRotation, kScale, kWeights };
enum class Interpolation { kLinear, kStep, kCubicSpline };

struct AnimationChannel {
  int node = -1;
  AnimationPath path = AnimationPath::kTranslation;
  Interpolation interpolation = Interpolation::kLinear;
  std::vector<float> times;  // seconds, strictly increasing
  // Per keyframe `width` numbers: 3 (translation, scale), 4 (rotation x, y, z, w) or one per
  // morph target (weights); CUBICSPLINE keeps in-tangent, value, out-tangent per keyframe, as
  // stored.
  int width = 3;
  std::vector<float> values;
};

struct NodeAnimation {
  std::string name;
  std::vector<AnimationChannel> channels;
  double duration_s = 0.0;  // the last keyframe over all channels
  // Whether a channel moves the node's transform (translation, rotation or scale).
  bool moves(int node) const;
};

// A node's local transform, T * R * S.
struct NodeTrs {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
  glm::mat4 matrix() const;
};

// The animation called `name` (empty: the file's first) of a parsed file. Throws SceneError
// starting with `file` and naming the field: no animations, no animation of that name (listing
// those there are), a sampler or node index out of range, an unknown interpolation or path,
// keyframe times that are not increasing, an output of the wrong length.
NodeAnimation read_animation(const tinygltf::Model& model, const std::string& name,
                             const std::string& file);
// The same from a .gltf/.glb file (gltf_input.h's checks).
NodeAnimation load_animation(const std::string& path, const std::string& name);

// `rest` (the node's own TRS) with every channel of `node` applied at `time_s`.
NodeTrs sample_node(const NodeAnimation& animation, int node, double time_s, NodeTrs rest);
// `rest` (the node's morph weights) with a weights channel of `node` applied at `time_s`.
std::vector<float> sample_weights(const NodeAnimation& animation, int node, double time_s,
                                  std::vector<float> rest);

}  // namespace skinsim::scene

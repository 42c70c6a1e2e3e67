#include "scene/gltf_animation.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/error.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_input.h"
#include "scene/gltf_primitive.h"

namespace skinsim::scene {

namespace {

Interpolation parse_interpolation(const std::string& text, const std::string& file,
                                  const std::string& where) {
  if (text == "LINEAR") return Interpolation::kLinear;
  if (text == "STEP") return Interpolation::kStep;
  if (text == "CUBICSPLINE") return Interpolation::kCubicSpline;
  throw SceneError(fmt::format("{}: {}.interpolation: '{}' is not LINEAR, STEP or CUBICSPLINE",
                               file, where, text));
}

AnimationChannel read_channel(const tinygltf::Model& model, const tinygltf::Animation& a,
                              const tinygltf::AnimationChannel& c, const std::string& file,
                              const std::string& where) {
  AnimationChannel out;
  if (c.target_node < 0 || static_cast<std::size_t>(c.target_node) >= model.nodes.size()) {
    throw SceneError(fmt::format("{}: {}.target.node: index {} out of range ({} nodes)", file,
                                 where, c.target_node, model.nodes.size()));
  }
  out.node = c.target_node;
  if (c.target_path == "translation") {
    out.path = AnimationPath::kTranslation;
  } else if (c.target_path == "rotation") {
    out.path = AnimationPath::kRotation;
  } else if (c.target_path == "scale") {
    out.path = AnimationPath::kScale;
  } else if (c.target_path == "weights") {
    out.path = AnimationPath::kWeights;
  } else {
    throw SceneError(
        fmt::format("{}: {}.target.path: '{}' is not translation, rotation, scale or weights", file,
                    where, c.target_path));
  }
  out.width = out.path == AnimationPath::kRotation ? 4 : 3;
  if (out.path == AnimationPath::kWeights) {
    const int mesh = model.nodes[static_cast<std::size_t>(out.node)].mesh;
    const std::size_t targets = mesh < 0 ? 0 : gltf::morph_target_count(model, mesh, file);
    if (targets == 0) {
      throw SceneError(
          fmt::format("{}: {}.target.node: node {} animates weights but has no mesh with morph "
                      "targets",
                      file, where, out.node));
    }
    out.width = static_cast<int>(targets);
  }
  if (c.sampler < 0 || static_cast<std::size_t>(c.sampler) >= a.samplers.size()) {
    throw SceneError(fmt::format("{}: {}.sampler: index {} out of range ({} samplers)", file, where,
                                 c.sampler, a.samplers.size()));
  }
  const tinygltf::AnimationSampler& s = a.samplers[static_cast<std::size_t>(c.sampler)];
  const std::string sampler =
      fmt::format("{}.samplers[{}]", where.substr(0, where.find('.')), c.sampler);
  out.interpolation = parse_interpolation(s.interpolation, file, sampler);
  out.times = gltf::read_floats(model, s.input, 1, gltf::AttributeFormat::kFloatOnly, file,
                                sampler + ".input");
  if (out.times.empty()) {
    throw SceneError(fmt::format("{}: {}.input: no keyframes", file, sampler));
  }
  for (std::size_t k = 0; k < out.times.size(); ++k) {
    if (!std::isfinite(out.times[k]) || out.times[k] < 0.0f ||
        (k > 0 && !(out.times[k] > out.times[k - 1]))) {
      throw SceneError(fmt::format(
          "{}: {}.input: keyframe times must be finite, >= 0 and increasing (time {} is {})", file,
          sampler, k, out.times[k]));
    }
  }
  const std::size_t per_key = out.interpolation == Interpolation::kCubicSpline ? 3 : 1;
  if (out.path == AnimationPath::kWeights) {
    // A SCALAR output, one weight per morph target per keyframe (spec 3.11.2).
    out.values = gltf::read_floats(model, s.output, 1, gltf::AttributeFormat::kFloatOrNormalized,
                                   file, sampler + ".output");
    const std::size_t expected = out.times.size() * per_key * static_cast<std::size_t>(out.width);
    if (out.values.size() != expected) {
      throw SceneError(fmt::format(
          "{}: {}.output: {} weights for {} keyframes of node {}'s {} morph targets; {} "
          "expects {}",
          file, sampler, out.values.size(), out.times.size(), out.node, out.width, s.interpolation,
          expected));
    }
    return out;
  }
  const auto n = static_cast<std::size_t>(out.width);
  out.values = gltf::read_floats(model, s.output, out.width, gltf::AttributeFormat::kFloatOnly,
                                 file, sampler + ".output");
  if (out.values.size() != out.times.size() * per_key * n) {
    throw SceneError(fmt::format("{}: {}.output: {} elements for {} keyframes; {} expects {}", file,
                                 sampler, out.values.size() / n, out.times.size(), s.interpolation,
                                 out.times.size() * per_key));
  }
  return out;
}

// Element `k` (a keyframe's value, or with CUBICSPLINE its tangent): `width` numbers.
std::vector<float> element(const AnimationChannel& c, std::size_t k) {
  const auto begin = c.values.begin() + static_cast<std::ptrdiff_t>(k * c.width);
  return {begin, begin + c.width};
}

// The channel's value at `t` (spec 3.11 and its appendix C, "Animation sampler interpolation
// modes"), component by component except a LINEAR rotation's slerp.
std::vector<float> sample(const AnimationChannel& c, float t) {
  const bool cubic = c.interpolation == Interpolation::kCubicSpline;
  const auto value = [&](std::size_t key) { return element(c, cubic ? 3 * key + 1 : key); };
  if (t <= c.times.front()) return value(0);
  if (t >= c.times.back()) return value(c.times.size() - 1);
  const std::size_t next = static_cast<std::size_t>(
      std::upper_bound(c.times.begin(), c.times.end(), t) - c.times.begin());
  const std::size_t key = next - 1;
  const float td = c.times[next] - c.times[key];
  const float s = (t - c.times[key]) / td;
  const std::vector<float> a = value(key), b = value(next);
  std::vector<float> out(a.size());
  switch (c.interpolation) {
    case Interpolation::kStep:
      return a;
    case Interpolation::kLinear:
      if (c.path == AnimationPath::kRotation) {
        const glm::quat q =
            glm::slerp(glm::quat(a[3], a[0], a[1], a[2]), glm::quat(b[3], b[0], b[1], b[2]), s);
        return {q.x, q.y, q.z, q.w};
      }
      for (std::size_t i = 0; i < out.size(); ++i) out[i] = a[i] * (1.0f - s) + b[i] * s;
      return out;
    case Interpolation::kCubicSpline: {
      const float s2 = s * s, s3 = s2 * s;
      const std::vector<float> out_tangent = element(c, 3 * key + 2),
                               in_tangent = element(c, 3 * next);
      for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = (2 * s3 - 3 * s2 + 1) * a[i] + td * (s3 - 2 * s2 + s) * out_tangent[i] +
                 (-2 * s3 + 3 * s2) * b[i] + td * (s3 - s2) * in_tangent[i];
      }
      return out;
    }
  }
  return a;
}

}  // namespace

bool NodeAnimation::moves(int node) const {
  return std::any_of(channels.begin(), channels.end(), [node](const AnimationChannel& c) {
    return c.node == node && c.path != AnimationPath::kWeights;
  });
}

glm::mat4 NodeTrs::matrix() const {
  return glm::scale(glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation), scale);
}

NodeAnimation read_animation(const tinygltf::Model& model, const std::string& name,
                             const std::string& file) {
  if (model.animations.empty()) {
    throw SceneError(fmt::format("{}: animations: the file has none", file));
  }
  std::size_t index = 0;
  if (!name.empty()) {
    std::vector<std::string> names;
    for (const tinygltf::Animation& a : model.animations) names.push_back(a.name);
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) {
      throw SceneError(fmt::format("{}: animations: no animation named '{}' (there are: {})", file,
                                   name, fmt::join(names, ", ")));
    }
    index = static_cast<std::size_t>(found - names.begin());
  }
  const tinygltf::Animation& a = model.animations[index];
  NodeAnimation out;
  out.name = a.name.empty() ? fmt::format("animation {}", index) : a.name;
  for (std::size_t i = 0; i < a.channels.size(); ++i) {
    const std::string where = fmt::format("animations[{}].channels[{}]", index, i);
    out.channels.push_back(read_channel(model, a, a.channels[i], file, where));
    out.duration_s =
        std::max(out.duration_s, static_cast<double>(out.channels.back().times.back()));
  }
  return out;
}

NodeAnimation load_animation(const std::string& path, const std::string& name) {
  return read_animation(gltf::parse_gltf_file(path), name, path);
}

NodeTrs sample_node(const NodeAnimation& animation, int node, double time_s, NodeTrs rest) {
  for (const AnimationChannel& c : animation.channels) {
    if (c.node != node || c.path == AnimationPath::kWeights) continue;
    const std::vector<float> v = sample(c, static_cast<float>(time_s));
    switch (c.path) {
      case AnimationPath::kTranslation:
        rest.translation = {v[0], v[1], v[2]};
        break;
      case AnimationPath::kRotation:
        rest.rotation = glm::normalize(glm::quat(v[3], v[0], v[1], v[2]));
        break;
      case AnimationPath::kScale:
        rest.scale = {v[0], v[1], v[2]};
        break;
      case AnimationPath::kWeights:
        break;
    }
  }
  return rest;
}

std::vector<float> sample_weights(const NodeAnimation& animation, int node, double time_s,
                                  std::vector<float> rest) {
  for (const AnimationChannel& c : animation.channels) {
    if (c.node == node && c.path == AnimationPath::kWeights) {
      rest = sample(c, static_cast<float>(time_s));
    }
  }
  return rest;
}

}  // namespace skinsim::scene

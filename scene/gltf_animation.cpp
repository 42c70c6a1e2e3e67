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

namespace skinsim::scene {

namespace {

int components(AnimationPath path) {
  return path == AnimationPath::kRotation ? 4 : 3;
}

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
  } else {
    throw SceneError(fmt::format("{}: {}.target.path: '{}' is not translation, rotation or scale",
                                 file, where, c.target_path));
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
  const int n = components(out.path);
  out.values = gltf::read_floats(model, s.output, n, gltf::AttributeFormat::kFloatOnly, file,
                                 sampler + ".output");
  const std::size_t per_key = out.interpolation == Interpolation::kCubicSpline ? 3 : 1;
  if (out.values.size() != out.times.size() * per_key * static_cast<std::size_t>(n)) {
    throw SceneError(fmt::format("{}: {}.output: {} elements for {} keyframes; {} expects {}", file,
                                 sampler, out.values.size() / static_cast<std::size_t>(n),
                                 out.times.size(), s.interpolation, out.times.size() * per_key));
  }
  return out;
}

// Element `k` (a keyframe's value, or with CUBICSPLINE its tangent) as a vec4 (w = 0 for vec3).
glm::vec4 element(const AnimationChannel& c, std::size_t k) {
  const int n = components(c.path);
  glm::vec4 v(0.0f);
  for (int i = 0; i < n; ++i) v[i] = c.values[k * static_cast<std::size_t>(n) + i];
  return v;
}

// The channel's value at `t` (spec 3.11 and its appendix C, "Animation sampler interpolation
// modes").
glm::vec4 sample(const AnimationChannel& c, float t) {
  const bool cubic = c.interpolation == Interpolation::kCubicSpline;
  const auto value = [&](std::size_t key) { return element(c, cubic ? 3 * key + 1 : key); };
  if (t <= c.times.front()) return value(0);
  if (t >= c.times.back()) return value(c.times.size() - 1);
  const std::size_t next = static_cast<std::size_t>(
      std::upper_bound(c.times.begin(), c.times.end(), t) - c.times.begin());
  const std::size_t key = next - 1;
  const float td = c.times[next] - c.times[key];
  const float s = (t - c.times[key]) / td;
  switch (c.interpolation) {
    case Interpolation::kStep:
      return value(key);
    case Interpolation::kLinear:
      if (c.path == AnimationPath::kRotation) {
        const glm::vec4 a = value(key), b = value(next);
        const glm::quat q =
            glm::slerp(glm::quat(a.w, a.x, a.y, a.z), glm::quat(b.w, b.x, b.y, b.z), s);
        return {q.x, q.y, q.z, q.w};
      }
      return glm::mix(value(key), value(next), s);
    case Interpolation::kCubicSpline: {
      const float s2 = s * s, s3 = s2 * s;
      const glm::vec4 out_tangent = element(c, 3 * key + 2), in_tangent = element(c, 3 * next);
      return (2 * s3 - 3 * s2 + 1) * value(key) + td * (s3 - 2 * s2 + s) * out_tangent +
             (-2 * s3 + 3 * s2) * value(next) + td * (s3 - s2) * in_tangent;
    }
  }
  return value(key);
}

}  // namespace

bool NodeAnimation::moves(int node) const {
  return std::any_of(channels.begin(), channels.end(),
                     [node](const AnimationChannel& c) { return c.node == node; });
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
    if (a.channels[i].target_path == "weights") {
      out.skipped.push_back(where + ": weights (morph targets are not played)");
      continue;
    }
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
    if (c.node != node) continue;
    const glm::vec4 v = sample(c, static_cast<float>(time_s));
    switch (c.path) {
      case AnimationPath::kTranslation:
        rest.translation = glm::vec3(v);
        break;
      case AnimationPath::kRotation:
        rest.rotation = glm::normalize(glm::quat(v.w, v.x, v.y, v.z));
        break;
      case AnimationPath::kScale:
        rest.scale = glm::vec3(v);
        break;
    }
  }
  return rest;
}

}  // namespace skinsim::scene

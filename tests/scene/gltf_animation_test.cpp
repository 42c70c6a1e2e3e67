// glTF animations (scene/gltf_animation.h): a small animated quad made here plays its keyframes
// exactly, interpolates between them as the glTF 2.0 spec says for LINEAR, STEP and
// CUBICSPLINE, and bad input raises SceneError naming the file and the field.
#include "scene/gltf_animation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "scene/error.h"
#include "tests/scene/gltf_fixture.h"

namespace skinsim::scene {
namespace {

using testing::GltfFixture;

// The quad of add_quad_mesh (node 0) with one animation of `channels` over `samplers`.
std::string animated_quad(GltfFixture& f, const nlohmann::json& samplers,
                          const nlohmann::json& channels, const std::string& name = "turn") {
  f.add_quad_mesh(true, true);
  f.json()["animations"] = {{{"name", name}, {"samplers", samplers}, {"channels", channels}}};
  return f.write_gltf("animated");
}

// Rotations about +Y by 0, 90 and 180 degrees at 0, 1 and 2 s.
nlohmann::json turn_sampler(GltfFixture& f, const std::string& interpolation) {
  const float h = std::sqrt(0.5f);
  const int input = f.add_floats({0.0f, 1.0f, 2.0f}, "SCALAR");
  const int output = f.add_floats({0, 0, 0, 1, 0, h, 0, h, 0, 1, 0, 0}, "VEC4");
  return {{"input", input}, {"output", output}, {"interpolation", interpolation}};
}

const nlohmann::json kRotateNode0 = {
    {{"sampler", 0}, {"target", {{"node", 0}, {"path", "rotation"}}}}};

float yaw_degrees(const NodeTrs& trs) {
  const glm::vec3 x = glm::mat3_cast(trs.rotation) * glm::vec3(1, 0, 0);
  return glm::degrees(std::atan2(-x.z, x.x));
}

TEST(GltfAnimation, LinearRotationPlaysKeyframesAndSlerpsBetween) {
  GltfFixture f("anim_linear");
  const nlohmann::json sampler = turn_sampler(f, "LINEAR");
  const NodeAnimation a =
      load_animation(animated_quad(f, nlohmann::json::array({sampler}), kRotateNode0), "turn");
  EXPECT_EQ(a.name, "turn");
  EXPECT_DOUBLE_EQ(a.duration_s, 2.0);
  EXPECT_NEAR(yaw_degrees(sample_node(a, 0, 0.0, {})), 0.0f, 1e-4f);
  EXPECT_NEAR(yaw_degrees(sample_node(a, 0, 1.0, {})), 90.0f, 1e-4f);
  EXPECT_NEAR(std::abs(yaw_degrees(sample_node(a, 0, 2.0, {}))), 180.0f, 1e-4f);
  EXPECT_NEAR(yaw_degrees(sample_node(a, 0, 0.5, {})), 45.0f, 1e-3f);  // slerp: constant speed
  EXPECT_NEAR(yaw_degrees(sample_node(a, 0, 1.25, {})), 112.5f, 1e-3f);
  EXPECT_NEAR(std::abs(yaw_degrees(sample_node(a, 0, 5.0, {}))), 180.0f, 1e-4f);  // held after
  // A node the animation does not move keeps its own transform.
  NodeTrs rest;
  rest.translation = {1, 2, 3};
  EXPECT_EQ(sample_node(a, 1, 0.5, rest).translation, rest.translation);
}

TEST(GltfAnimation, StepHoldsEachKeyframeUntilTheNext) {
  GltfFixture f("anim_step");
  const nlohmann::json sampler = turn_sampler(f, "STEP");
  const NodeAnimation a =
      load_animation(animated_quad(f, nlohmann::json::array({sampler}), kRotateNode0), "");
  EXPECT_NEAR(yaw_degrees(sample_node(a, 0, 0.99, {})), 0.0f, 1e-4f);
  EXPECT_NEAR(yaw_degrees(sample_node(a, 0, 1.0, {})), 90.0f, 1e-4f);
  EXPECT_NEAR(yaw_degrees(sample_node(a, 0, 1.99, {})), 90.0f, 1e-4f);
}

TEST(GltfAnimation, CubicSplineTranslationFollowsTheHermiteCurve) {
  GltfFixture f("anim_cubic");
  const int input = f.add_floats({0.0f, 2.0f}, "SCALAR");
  // Per keyframe: in-tangent, value, out-tangent. From x = 0 to x = 2 over 2 s, leaving the
  // first keyframe at 1 unit/s along x.
  const int output = f.add_floats({0, 0, 0, 0, 0, 0, 1, 0, 0,  //
                                   0, 0, 0, 2, 0, 0, 0, 0, 0},
                                  "VEC3");
  const nlohmann::json sampler = {
      {"input", input}, {"output", output}, {"interpolation", "CUBICSPLINE"}};
  const nlohmann::json channels = {
      {{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}};
  const NodeAnimation a =
      load_animation(animated_quad(f, nlohmann::json::array({sampler}), channels), "turn");
  EXPECT_EQ(sample_node(a, 0, 0.0, {}).translation, glm::vec3(0, 0, 0));
  EXPECT_EQ(sample_node(a, 0, 2.0, {}).translation, glm::vec3(2, 0, 0));
  // s = 0.5, td = 2: (-2s^3 + 3s^2) * 2 + td (s^3 - 2s^2 + s) * 1 = 1 + 0.25.
  EXPECT_NEAR(sample_node(a, 0, 1.0, {}).translation.x, 1.25f, 1e-6f);
  EXPECT_EQ(sample_node(a, 0, 1.0, {}).translation.y, 0.0f);
}

// `mutate` breaks the animated quad; loading must fail naming `expected`.
void expect_error(const std::string& test, const std::function<void(nlohmann::json&)>& mutate,
                  const std::string& expected, const std::string& name = "turn") {
  GltfFixture f(test);
  const nlohmann::json sampler = turn_sampler(f, "LINEAR");
  f.add_quad_mesh(true, true);
  f.json()["animations"] = {
      {{"name", "turn"}, {"samplers", {sampler}}, {"channels", kRotateNode0}}};
  mutate(f.json());
  const std::string path = f.write_gltf("broken");
  try {
    load_animation(path, name);
    FAIL() << "no error for " << expected;
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path, 0), 0u) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }
}

TEST(GltfAnimation, BadInputNamesTheField) {
  expect_error(
      "anim_none", [](nlohmann::json& j) { j.erase("animations"); },
      "animations: the file has none");
  expect_error(
      "anim_name", [](nlohmann::json&) {}, "no animation named 'walk' (there are: turn)", "walk");
  expect_error(
      "anim_sampler", [](nlohmann::json& j) { j["animations"][0]["channels"][0]["sampler"] = 3; },
      "animations[0].channels[0].sampler: index 3 out of range (1 samplers)");
  expect_error(
      "anim_node",
      [](nlohmann::json& j) { j["animations"][0]["channels"][0]["target"]["node"] = 9; },
      "animations[0].channels[0].target.node: index 9 out of range");
  expect_error(
      "anim_interp",
      [](nlohmann::json& j) { j["animations"][0]["samplers"][0]["interpolation"] = "EASE"; },
      "animations[0].samplers[0].interpolation: 'EASE'");
  expect_error(
      "anim_cubic_len",
      [](nlohmann::json& j) { j["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE"; },
      "animations[0].samplers[0].output: 3 elements for 3 keyframes");
}

}  // namespace
}  // namespace skinsim::scene

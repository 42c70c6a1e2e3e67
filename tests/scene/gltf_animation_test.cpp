// glTF animations (scene/gltf_animation.h): a small animated quad made here plays its keyframes
// exactly, interpolates between them as the glTF 2.0 spec says for LINEAR, STEP and
// CUBICSPLINE, morphs by its targets' weights (the mesh's defaults, the node's, the
// animation's), and bad input raises SceneError naming the file and the field.
#include "scene/gltf_animation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include "scene/error.h"
#include "scene/gltf_loader.h"
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

// `load` must throw SceneError starting with `path` and naming `expected`.
void expect_scene_error(const std::string& path, const std::function<void()>& load,
                        const std::string& expected) {
  try {
    load();
    FAIL() << "no error for " << expected;
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path, 0), 0u) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }
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
  expect_scene_error(
      path, [&] { load_animation(path, name); }, expected);
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

// The quad (vertex 0 at the origin) with two morph targets: the first lifts vertex 0 by 1 along
// z, the second moves it by 1 along x and its normal towards -x; weights 0.5, 0 by default.
void add_morph_targets(GltfFixture& f) {
  f.add_quad_mesh(true, true);
  const int lift = f.add_floats({0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
  const int slide = f.add_floats({1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
  const int tilt = f.add_floats({-1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3");
  f.json()["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", lift}},
                                                       {{"POSITION", slide}, {"NORMAL", tilt}}};
  f.json()["meshes"][0]["weights"] = {0.5, 0.0};
}

// Weights (0, 0), (1, 0), (1, 1) at 0, 1 and 2 s.
nlohmann::json weights_sampler(GltfFixture& f, const std::string& interpolation) {
  const int input = f.add_floats({0.0f, 1.0f, 2.0f}, "SCALAR");
  const int output = f.add_floats({0, 0, 1, 0, 1, 1}, "SCALAR");
  return {{"input", input}, {"output", output}, {"interpolation", interpolation}};
}

const nlohmann::json kMorphNode0 = {
    {{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}};

// Vertex 0 of the scene the file makes posed at `time_s` (no animation: `animation` null).
glm::vec3 vertex0(const std::string& path, const NodeAnimation* animation, double time_s,
                  glm::vec3* normal = nullptr) {
  LoadOptions options;
  options.warn = [](const std::string&) {};
  const Scene scene = PosedGltf(path, options).pose(animation, time_s);
  if (normal) *normal = scene.meshes.at(0).normals.at(0);
  return scene.meshes.at(0).positions.at(0);
}

TEST(GltfAnimation, MorphWeightsFromTheMeshTheNodeAndTheAnimation) {
  GltfFixture f("anim_morph");
  add_morph_targets(f);
  const std::string still = f.write_gltf("still");
  EXPECT_EQ(vertex0(still, nullptr, 0.0), glm::vec3(0.0f, 0.0f, 0.5f));  // the mesh's 0.5, 0
  f.json()["nodes"][0]["weights"] = {0.25, 1.0};                         // the node's override
  glm::vec3 normal;
  EXPECT_EQ(vertex0(f.write_gltf("node"), nullptr, 0.0, &normal), glm::vec3(1.0f, 0.0f, 0.25f));
  // NORMAL (0, 0, 1) + 1 * (-1, 0, 0), made unit length.
  EXPECT_NEAR(normal.x, -std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(normal.z, std::sqrt(0.5f), 1e-6f);

  f.json()["animations"] = {{{"name", "morph"},
                             {"samplers", nlohmann::json::array({weights_sampler(f, "LINEAR")})},
                             {"channels", kMorphNode0}}};
  const std::string animated = f.write_gltf("animated");
  const NodeAnimation a = load_animation(animated, "morph");
  EXPECT_DOUBLE_EQ(a.duration_s, 2.0);
  EXPECT_FALSE(a.moves(0));  // weights do not move the node's transform
  EXPECT_EQ(vertex0(animated, &a, 0.0), glm::vec3(0.0f, 0.0f, 0.0f));  // keyframes, exactly
  EXPECT_EQ(vertex0(animated, &a, 1.0), glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(vertex0(animated, &a, 2.0), glm::vec3(1.0f, 0.0f, 1.0f));
  EXPECT_EQ(vertex0(animated, &a, 0.5), glm::vec3(0.0f, 0.0f, 0.5f));  // linear between
  EXPECT_EQ(vertex0(animated, &a, 1.25), glm::vec3(0.25f, 0.0f, 1.0f));
  EXPECT_EQ(vertex0(animated, &a, 9.0), glm::vec3(1.0f, 0.0f, 1.0f));  // held after the last
  EXPECT_EQ(sample_weights(a, 0, 1.5, {}), (std::vector<float>{1.0f, 0.5f}));
  EXPECT_EQ(sample_weights(a, 1, 1.5, {0.3f}), (std::vector<float>{0.3f}));  // not animated

  f.json()["animations"][0]["samplers"][0] = weights_sampler(f, "STEP");
  const std::string step = f.write_gltf("step");
  const NodeAnimation s = load_animation(step, "morph");
  EXPECT_EQ(vertex0(step, &s, 1.99), glm::vec3(0.0f, 0.0f, 1.0f));
}

// `mutate` breaks the morph-animated quad; loading the scene and its animation must fail
// naming `expected`.
void expect_morph_error(const std::string& test, const std::function<void(GltfFixture&)>& mutate,
                        const std::string& expected) {
  GltfFixture f(test);
  add_morph_targets(f);
  f.json()["animations"] = {{{"name", "morph"},
                             {"samplers", nlohmann::json::array({weights_sampler(f, "LINEAR")})},
                             {"channels", kMorphNode0}}};
  mutate(f);
  const std::string path = f.write_gltf("broken");
  expect_scene_error(
      path,
      [&] {
        const NodeAnimation a = load_animation(path, "morph");
        vertex0(path, &a, 0.5);
      },
      expected);
}

TEST(GltfAnimation, BadMorphInputNamesTheField) {
  expect_morph_error(
      "morph_mesh_weights",
      [](GltfFixture& f) {
        f.json()["meshes"][0]["weights"] = {1, 0, 0};
      },
      "meshes[0].weights: 3 weights for 2 morph targets");
  expect_morph_error(
      "morph_node_weights", [](GltfFixture& f) { f.json()["nodes"][0]["weights"] = {1}; },
      "nodes[0].weights: 1 weights for 2 morph targets (meshes[0])");
  expect_morph_error(
      "morph_target_count",
      [](GltfFixture& f) {
        f.json()["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] =
            f.add_floats({0, 0, 1, 0, 0, 0, 0, 0, 0}, "VEC3");
      },
      "meshes[0].primitives[0].targets[0].POSITION: 3 elements, POSITION has 4");
  expect_morph_error(
      "morph_output",
      [](GltfFixture& f) {
        f.json()["animations"][0]["samplers"][0]["output"] = f.add_floats({0, 1, 1}, "SCALAR");
      },
      "animations[0].samplers[0].output: 3 weights for 3 keyframes of node 0's 2 morph "
      "targets; LINEAR expects 6");
  expect_morph_error(
      "morph_no_targets",
      [](GltfFixture& f) {
        f.json()["meshes"][0]["primitives"][0].erase("targets");
        f.json()["meshes"][0].erase("weights");
      },
      "animations[0].channels[0].target.node: node 0 animates weights but has no mesh with "
      "morph targets");
  expect_morph_error(
      "morph_primitives",
      [](GltfFixture& f) {
        nlohmann::json second = f.json()["meshes"][0]["primitives"][0];
        second["targets"] = nlohmann::json::array();
        f.json()["meshes"][0]["primitives"].push_back(second);
      },
      "meshes[0].primitives[1].targets: 0 morph targets, primitives[0] has 2");
}

}  // namespace
}  // namespace skinsim::scene

// A small animated glTF for the sequence tests: a skin quad 2 m in front of a perspective
// camera, with one animation "slide" moving node `animated` (0: the quad, 1: the camera) 0.6 m
// along +x over 1 s.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/scene/gltf_fixture.h"

namespace skinsim::test {

inline std::string slide_scene(skinsim::scene::testing::GltfFixture& f, int animated) {
  f.add_quad_mesh(true, true);
  f.json()["nodes"][0]["translation"] = {-0.5, -0.5, -2.0};
  f.json()["materials"] = {{{"name", "skin"}}};
  f.json()["meshes"][0]["primitives"][0]["material"] = 0;
  f.json()["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 10.0}}}}};
  f.json()["nodes"].push_back({{"camera", 0}, {"translation", {0.0, 0.0, 0.0}}});
  f.json()["scenes"][0]["nodes"].push_back(1);
  const nlohmann::json rest = f.json()["nodes"][animated]["translation"];
  const std::vector<float> start = rest.get<std::vector<float>>();
  const int input = f.add_floats({0.0f, 1.0f}, "SCALAR");
  const int output =
      f.add_floats({start[0], start[1], start[2], start[0] + 0.6f, start[1], start[2]}, "VEC3");
  f.json()["animations"] = {
      {{"name", "slide"},
       {"samplers", nlohmann::json::array({{{"input", input}, {"output", output}}})},
       {"channels",
        nlohmann::json::array(
            {{{"sampler", 0}, {"target", {{"node", animated}, {"path", "translation"}}}}})}}};
  return f.write_gltf("slide");
}

}  // namespace skinsim::test

// Texture bindings and uniforms of the skin shaders: the mobile pipeline's final shader
// (skin.h) defines them, and the other techniques' skin shaders build on them.
#pragma once

#include <glm/vec3.hpp>

#include "pipeline/shaders/lights.h"

namespace skinsim::pipeline::shaders {

struct SkinBindings {
  static constexpr int kAlbedo = 0;
  static constexpr int kNormalMap = 1;
  static constexpr int kEnvironment = 2;
  static constexpr int kIrradiance = 3;
  static constexpr int kBrdfLut = 4;
};

struct SkinUniforms {
  glm::vec3 eye{0.0f};
  LightUniforms lights;
  glm::vec3 albedo_factor{1.0f};
  glm::vec3 layer_mix{0.5f};  // fraction of each channel's diffuse light that scatters wide
  float reflectivity = 1.0f;
  float specular_intensity = 0.18f;  // rho_s
  float lobe1_weight = 0.85f;
  float lobe2_weight = 0.15f;
  float lut_lod = 0.0f;
  float environment_intensity = 1.0f;
};

}  // namespace skinsim::pipeline::shaders

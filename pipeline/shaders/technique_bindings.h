// Texture bindings of the comparison techniques' final skin shaders. Albedo, normal map,
// environment and BRDF LUT sit where the mobile shader has them (skin_uniforms.h).
#pragma once

#include "pipeline/shaders/skin_uniforms.h"

namespace skinsim::pipeline::shaders {

struct TechniqueBindings {
  static constexpr int kAlbedo = SkinBindings::kAlbedo;
  static constexpr int kNormalMap = SkinBindings::kNormalMap;
  static constexpr int kEnvironment = SkinBindings::kEnvironment;  // cube slot
  static constexpr int kDiffusion = 3;         // screen-space or UV-space diffused light
  static constexpr int kPreintegratedLut = 3;  // pre-integrated (N.L, curvature) LUT
  static constexpr int kBrdfLut = SkinBindings::kBrdfLut;
  static constexpr int kCurvature = 5;  // baked curvature in UV space
};

}  // namespace skinsim::pipeline::shaders

// Everything that is neither skin nor eye: Lambert with a base colour texture.
#pragma once

#include "pipeline/shaders/gamma.h"
#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

struct BackgroundFS {
  static constexpr const char* kName = "background_fs";
  struct Uniforms {
    LightUniforms lights;
    glm::vec3 albedo_factor{1.0f};
  };
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const vec4 base = tex.sample(0, in.texcoord(SurfaceSlots::kUv));
    const vec3 n = sl::normalize(in.v3(SurfaceSlots::kNormal));
    const vec3 albedo = decode_gamma<GammaMode::kSquare>(sl::xyz(base)) * u.albedo_factor;
    const auto visibility = key_visibility<L>(in, tex, u.lights, SurfaceSlots::kLight);
    const vec3 light = lambert_irradiance<L>(n, vec3(visibility), u.lights);
    return vec4(encode_gamma<GammaMode::kSquare>(albedo * light), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders

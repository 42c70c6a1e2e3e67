// Eyes: no scattering; a glossy cornea reflecting the sharp environment (a dependent cube
// read along the reflection vector), a tight highlight, and a diffuse iris/sclera.
#pragma once

#include "pipeline/shaders/gamma.h"
#include "pipeline/shaders/surface_vs.h"

namespace skinsim::pipeline::shaders {

struct EyeFS {
  static constexpr const char* kName = "eye_fs";
  struct Uniforms {
    glm::vec3 eye{0.0f};
    LightUniforms lights;
    glm::vec3 albedo_factor{1.0f};
    float cornea_f0 = 0.04f;  // water-like cornea, IOR ~1.38
    float highlight_power = 256.0f;
  };
  static constexpr int kAlbedo = 0;
  static constexpr int kEnvironment = 2;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const vec4 base = tex.sample(kAlbedo, in.texcoord(SurfaceSlots::kUv));
    const vec3 n = sl::normalize(in.v3(SurfaceSlots::kNormal));
    const vec3 v = sl::normalize(vec3(u.eye) - in.v3(SurfaceSlots::kWorldPos));
    const auto visibility = key_visibility<L>(in, tex, u.lights, SurfaceSlots::kLight);
    const vec3 l(u.lights.direction[0]);
    const vec3 h = sl::normalize(v + l);
    const vec3 r = sl::reflect(-v, n);
    const vec4 env = tex.sample_cube_lod(kEnvironment, r, 0.0f);
    const auto n_dot_v = sl::saturate(sl::dot(n, v));
    const auto one_minus = 1.0f - n_dot_v;
    const auto one_minus2 = one_minus * one_minus;
    const auto fresnel = u.cornea_f0 + (1.0f - u.cornea_f0) * (one_minus2 * one_minus2 * one_minus);
    const auto highlight = sl::pow(sl::saturate(sl::dot(n, h)), u.highlight_power);
    const vec3 albedo = decode_gamma<GammaMode::kSquare>(sl::xyz(base)) * u.albedo_factor;
    const vec3 diffuse = albedo * lambert_irradiance<L>(n, vec3(visibility), u.lights);
    const vec3 color =
        diffuse + vec3(u.lights.radiance[0]) * (highlight * visibility) + sl::xyz(env) * fresnel;
    return vec4(encode_gamma<GammaMode::kSquare>(color), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders

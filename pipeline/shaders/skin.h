// Pass 3 of the GPU Pro 5 mobile skin pipeline, and its single-pass LOD variant.
//
// Final shading reads four independent textures (albedo + reflectivity, normal map, the
// environment cube along the per-vertex normal, the blurred irradiance buffer). Diffuse
// light is the two-layer mix: the sharp per-pixel light (epidermis) and the blurred buffer
// (subdermal scattering), mixed per channel (diffusion.h), times albedo and the specular
// model's energy-conservation term. Specular is the `specular` knob (specular.h): by
// default, as in GPU Pro 5, one dependent read of the BRDF LUT at (N.H, N.V), whose LOD
// selects roughness, giving the two Kelemen/Szirmay-Kalos lobes and the pre-integrated
// Fresnel that scales the environment with the reflectivity map; the analytic models
// replace that read with ALU.
#pragma once

#include "pipeline/shaders/irradiance.h"
#include "pipeline/shaders/specular.h"

namespace skinsim::pipeline::shaders {

template <GammaMode kGamma, SpecularModel kSpec>
struct SkinFS {
  static constexpr ShaderName kNameText =
      shader_name({"skin_fs", specular_suffix(kSpec), gamma_suffix(kGamma)});
  static constexpr const char* kName = kNameText.text;
  using Uniforms = TechniqueUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u);
    const vec4 buffer = tex.sample(SkinBindings::kIrradiance, in.screen_texcoord());

    // Sharp light of every light (the key's shadowed, tinted) plus ambient; transmission is
    // in the buffer, with the rest of the scattered light.
    const vec3 sharp = lambert_irradiance<L>(s.normal, tinted<L>(s.visibility, u.lights), u.lights);
    // The buffer holds blurred light premultiplied by coverage a; where a < 1 (silhouettes)
    // the sharp light fills in: mix(sharp, blurred / a, layer_mix * a).
    const vec3 wide = vec3(u.layer_mix);
    const vec3 diffuse_light =
        sharp * (1.0f - wide * sl::w(buffer)) + sl::xyz(buffer) * (wide * kIrradianceRange);
    return skin_color<kGamma, kSpec, L>(s, tex, u, diffuse_light);
  }
};

// Distant skin: one pass, no buffer. Scattering is approximated by bending each channel's
// normal toward the vertex normal by that channel's scattering fraction (GPU Pro 5 LOD).
template <GammaMode kGamma, SpecularModel kSpec>
struct SkinLodFS {
  static constexpr ShaderName kNameText =
      shader_name({"skin_lod_fs", specular_suffix(kSpec), gamma_suffix(kGamma)});
  static constexpr const char* kName = kNameText.text;
  using Uniforms = TechniqueUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u);

    const vec3 n_r = sl::normalize(sl::mix(s.normal, s.vertex_normal, u.layer_mix.r));
    const vec3 n_g = sl::normalize(sl::mix(s.normal, s.vertex_normal, u.layer_mix.g));
    const vec3 n_b = sl::normalize(sl::mix(s.normal, s.vertex_normal, u.layer_mix.b));
    const vec3 key_vis = tinted<L>(s.visibility, u.lights);
    vec3 diffuse_light = vec3(u.lights.ambient) +
                         transmitted<L>(in, s.vertex_normal, u.lights, SurfaceSlots::kLight);
    for (int i = 0; i < u.lights.count; ++i) {
      const vec3 l(u.lights.direction[i]);
      const vec3 n_dot_l = sl::saturate(vec3(sl::dot(n_r, l), sl::dot(n_g, l), sl::dot(n_b, l)));
      diffuse_light = diffuse_light + light_radiance<L>(i, key_vis, u.lights) * n_dot_l;
    }
    return skin_color<kGamma, kSpec, L>(s, tex, u, diffuse_light);
  }
};

}  // namespace skinsim::pipeline::shaders

// The urp technique's skin shader: the URP skin shader article's PBR skin in one pass
// (docs/techniques.md, urp; ../shared/docs/skin-techniques.md sections 2, 3 and 6).
//   diffuse:  Penner's pre-integrated (N.L, curvature) LUT (preintegrated.h), curvature from
//             screen-space derivatives, red's normal from a blurred mip of the normal map and
//             green and blue blended towards the sharp one (scattered_diffuse);
//   detail:   a tiling pore normal map under a mask, added to both the sharp and (at a blurred
//             mip) the blurred normal, so the SSS terms see blurred pores;
//   specular: no metallic; the specular map's reflectivity (the albedo's alpha, as every skin
//             shader here) scales the dual-lobe GGX of direct light (specular.h, dual_ggx: two
//             roughnesses mixed in D, the mean in V) and a dual-lobe image-based term, one
//             environment lookup per lobe at that lobe's roughness mip;
//   occlusion: baked AO (a UV-space texture of the ray-cast per-vertex bake) times the ssao
//             pass's AO (ssao.h), times the key light's shadow with
//             a floor of 0.35 (shadow_in_ao), on ambient and image-based light;
//   shadow tint: the key light's shadow brightened and mapped to a dark skin colour (the
//             article's, or the shadow_tint knob's when it is set);
//   clear coat: a GGX lobe on the vertex normal (smooth, over the pores) whose Fresnel takes
//             its energy from the layers below, for direct and image-based light.
// Texture reads after the surface's albedo and normal map: the shadow map, the blurred normal
// mip, the detail map twice, the baked and screen-space AO, three LUT reads per light, three
// environment reads.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "pipeline/shaders/preintegrated.h"

namespace skinsim::pipeline::shaders {

struct UrpBindings {
  static constexpr int kAlbedo = TechniqueBindings::kAlbedo;
  static constexpr int kNormalMap = TechniqueBindings::kNormalMap;
  static constexpr int kBakedAo = 2;  // the diffuse cube's unit: urp reads no such cube
  static constexpr int kPreintegratedLut = TechniqueBindings::kPreintegratedLut;
  static constexpr int kDetailNormals = 4;  // the BRDF LUT's unit: urp does not read it
  static constexpr int kAo = 5;             // the blurred ssao buffer, read at the pixel
  static constexpr int kEnvironment = 7;    // cube slot: the mipmapped sharp environment
};

// The article's constants.
inline constexpr float kShadowAoFloor = 0.35f;  // the shadow folded into AO never below this
inline constexpr glm::vec3 kShadowSkinColor{0.11f, 0.025f, 0.012f};  // half3 in the article
inline constexpr float kClearCoatF0 = 0.04f;  // a dielectric coat, IOR 1.5 (Filament's coat)

// Ambient occlusion with the key light's shadow folded in: ao x max(shadow, 0.35).
template <class F>
F shadow_in_ao(const F& ao, const F& shadow) {
  return ao * sl::max(shadow, kShadowAoFloor);
}

// The shadow tint: the shadow term brightened (1 - (1 - s)^2, which lifts the penumbra and
// keeps 0 and 1) and mapped from the dark skin colour `dark` (s = 0) to white (s = 1).
template <class L>
typename L::vec3 shadow_tint(const typename L::f32& shadow,
                             const glm::vec3& dark = kShadowSkinColor) {
  using vec3 = typename L::vec3;
  const auto bright = shadow * (2.0f - shadow);
  return vec3(dark) + vec3(1.0f - dark) * bright;
}

// The clear coat over the layers below: they keep 1 - F of the light, the coat adds its own.
template <class L>
typename L::vec3 under_clear_coat(const typename L::vec3& below, const typename L::f32& fresnel,
                                  const typename L::vec3& coat) {
  return below * (1.0f - fresnel) + coat;
}

// The coat's Fresnel at cosine `cos_theta`, scaled by its strength.
template <class F>
F clear_coat_fresnel(float strength, const F& cos_theta) {
  return detail::schlick(kClearCoatF0, cos_theta) * strength;
}

// One light's coat lobe (half vector `half`): GGX D and Hammon's visibility on the coat
// normal, times its Fresnel (the BRDF D Vis F N.L; pi_ggx_d carries pi).
template <class L>
typename L::vec3 clear_coat_light(const typename L::vec3& n, const typename L::vec3& view,
                                  const typename L::vec3& l, const typename L::vec3& half,
                                  const typename L::vec3& radiance, float alpha,
                                  const typename L::f32& fresnel) {
  const auto n_dot_h = sl::saturate(sl::dot(n, half));
  const auto n_dot_l = sl::saturate(sl::dot(n, l));
  const auto n_dot_v = sl::saturate(sl::dot(n, view));
  const auto brdf = detail::pi_ggx_d(sl::max(n_dot_h * n_dot_h, 1e-4f), alpha * alpha) *
                    detail::ggx_visibility(n_dot_l, n_dot_v, alpha) * (1.0f / 3.14159265f);
  return radiance * (brdf * fresnel * n_dot_l);
}

// A texture read at the mesh uv scaled by `tiling`: a dependent read on the SGX (the
// coordinate is computed); executed with the scaled derivatives, so the map is filtered at
// its own mip.
template <class L>
typename L::vec4 sample_tiled(typename L::TexUnit& tex, int unit,
                              const decltype(std::declval<typename L::FragIn>().texcoord(0))& uv,
                              float tiling) {
  if constexpr (L::kExecutes) {
    return tex.sample(unit, sim::scaled(uv, tiling));
  } else if constexpr (std::is_same_v<L, sim::Emit>) {
    return tex.sample(unit, sim::EmitVarying<2>{uv.value * tiling});  // texture2D's derivatives
  } else {
    return tex.sample(unit, uv.value * tiling);
  }
}

// One specular lobe's image-based light as URP weighs it (BRDF.hlsl, EnvironmentBRDFSpecular):
// lerp(F0, grazing, (1 - N.V)^4) / (alpha^2 + 1), grazing = saturate(smoothness + F0) with
// smoothness = 1 - sqrt(alpha): rough lobes brighten less towards grazing than Schlick's.
// The lobe's weight is folded into `scale`.
struct EnvironmentLobe {
  float grazing = 1.0f;
  float scale = 1.0f;  // weight / (alpha^2 + 1)
};
inline EnvironmentLobe environment_lobe(float alpha, float weight, float f0) {
  return {std::clamp(1.0f - std::sqrt(alpha) + f0, 0.0f, 1.0f), weight / (alpha * alpha + 1.0f)};
}
template <class F>
F environment_brdf(float f0, const EnvironmentLobe& lobe, const F& grazing_weight) {
  return (f0 + (lobe.grazing - f0) * grazing_weight) * lobe.scale;
}

struct UrpUniforms : TechniqueUniforms {
  float normal_blur_lod = 3.0f;  // red's normal: the normal map's mip 3 (8 x 8 texels)
  bool ssao = true;
  bool detail_normals = true;
  float detail_tiling = 48.0f;   // detail repeats per mesh uv unit
  float detail_strength = 0.3f;  // the detail mask (a constant: the scenes have no mask map)
  float detail_blur_lod = 3.0f;  // the detail map's mip for the blurred normal
  bool clear_coat = true;
  float coat_strength = 0.3f;
  float coat_roughness = 0.1f;  // GGX alpha
  // Environment mips of the two specular lobes and the coat (Unity's roughness-to-mip).
  float lobe1_lod = 0.0f;
  float lobe2_lod = 0.0f;
  float coat_lod = 0.0f;
  glm::vec3 shadow_color = kShadowSkinColor;  // the shadow_tint knob's when set
  EnvironmentLobe lobe1_environment;
  EnvironmentLobe lobe2_environment;
};

template <GammaMode kGamma>
struct UrpFS {
  static constexpr ShaderName kNameText = shader_name({"urp_fs", gamma_suffix(kGamma)});
  static constexpr const char* kName = kNameText.text;
  using Uniforms = UrpUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    using B = UrpBindings;
    const auto uv = in.texcoord(SurfaceSlots::kUv);
    const vec4 base = tex.sample(B::kAlbedo, uv);
    const vec4 normal_map = tex.sample(B::kNormalMap, uv);
    SkinSurface<L> s;
    surface_terms<L, kGamma>(in, tex, u, base, normal_map, s);
    const vec4 tangent = in.v4(SurfaceSlots::kTangent);
    vec3 blurred = normal_mapped<L>(
        s.vertex_normal, tangent, tex.sample_lod(B::kNormalMap, uv.value, f32(u.normal_blur_lod)));
    if (u.detail_normals) {
      // Pore detail added in the tangent frame (the partial-derivative blend), weighted by
      // the mask.
      const vec3 t = sl::xyz(tangent);
      const vec3 b = sl::cross(s.vertex_normal, t) * sl::w(tangent);
      const auto add_detail = [&](const vec3& n, const vec4& map) {
        const vec3 d = sl::xyz(map) * 2.0f - 1.0f;
        return sl::normalize(n + (t * sl::x(d) + b * sl::y(d)) * u.detail_strength);
      };
      s.normal = add_detail(s.normal, sample_tiled<L>(tex, B::kDetailNormals, uv, u.detail_tiling));
      blurred = add_detail(blurred, tex.sample_lod(B::kDetailNormals, uv.value * u.detail_tiling,
                                                   f32(u.detail_blur_lod)));
    }
    const f32 curvature = derivative_curvature<L>(in, u.curvature_scale);
    f32 ao = sl::x(tex.sample(B::kBakedAo, uv));
    if (u.ssao) ao = ao * sl::x(tex.sample(B::kAo, in.screen_texcoord()));
    const f32 occlusion = shadow_in_ao(ao, s.visibility);
    const vec3 key_tint = shadow_tint<L>(s.visibility, u.shadow_color);
    const f32 n_dot_v = sl::saturate(sl::dot(s.normal, s.view));
    const f32 fresnel = detail::schlick(u.f0, n_dot_v);

    // Direct light: diffuse through the LUT, the dual GGX lobes, the coat over both.
    vec3 direct(0.0f);
    for (int i = 0; i < u.lights.count; ++i) {
      const vec3 l(u.lights.direction[i]);
      const vec3 diffuse = s.albedo * scattered_diffuse<L>(tex, s.normal, blurred, l, curvature) *
                           light_radiance<L>(i, key_tint, u.lights) * (1.0f - fresnel);
      const vec3 shadowed = light_radiance<L>(i, vec3(s.visibility), u.lights);
      vec3 light = diffuse + lobe_light<SpecularModel::kDualGgx, L>(s, tex, u, l, shadowed).light;
      if (u.clear_coat) {
        const vec3 half = sl::normalize(s.view + l);
        const f32 coat_f = clear_coat_fresnel(u.coat_strength, sl::saturate(sl::dot(s.view, half)));
        const vec3 coat = clear_coat_light<L>(s.vertex_normal, s.view, l, half, shadowed,
                                              u.coat_roughness, coat_f);
        light = under_clear_coat<L>(light, coat_f, coat);
      }
      direct = direct + light;
    }

    // Ambient and image-based light, occluded: one environment lookup per lobe.
    const auto environment = [&](const vec3& n, float lod) {
      return sl::xyz(tex.sample_cube_lod(B::kEnvironment, sl::reflect(-s.view, n), f32(lod)));
    };
    const f32 k = 1.0f - n_dot_v;
    const f32 k2 = k * k;
    const f32 grazing = k2 * k2;
    const vec3 lobes =
        environment(s.normal, u.lobe1_lod) * environment_brdf(u.f0, u.lobe1_environment, grazing) +
        environment(s.normal, u.lobe2_lod) * environment_brdf(u.f0, u.lobe2_environment, grazing);
    vec3 indirect = (s.albedo * vec3(u.lights.ambient) * (1.0f - fresnel) +
                     lobes * (s.reflectivity * u.environment_intensity)) *
                    occlusion;
    indirect =
        indirect + transmitted<L>(in, s.vertex_normal, u.lights, SurfaceSlots::kLight) * s.albedo;
    if (u.clear_coat) {
      const f32 coat_f =
          clear_coat_fresnel(u.coat_strength, sl::saturate(sl::dot(s.vertex_normal, s.view)));
      indirect = under_clear_coat<L>(indirect, coat_f,
                                     environment(s.vertex_normal, u.coat_lod) *
                                         (coat_f * u.environment_intensity * occlusion));
    }
    return vec4(encode_gamma<kGamma>(direct + indirect), 1.0f);
  }
};

}  // namespace skinsim::pipeline::shaders

// Penner & Borshukov pre-integrated skin (GPU Pro 2, 2011; docs/skin-techniques.md section
// 3): one pass. The diffuse light of each colour channel is a dependent read of the
// (N.L, curvature) LUT with that channel's own normal ("detail scattering"): red uses the
// blurred (vertex) normal, green and blue blend from the sharp normal towards it with
// f = saturate(1 - N_blur.L)^2 (green: 0.3 + 0.7 f, blue: f).
// Curvature: a baked, smoothed UV-space texture (independent read), or
// length(fwidth(N)) / length(fwidth(P)) from screen-space derivatives of the interpolated
// vertex normal and position (GLES2 OES_standard_derivatives), which is constant across
// each triangle: the known faceting noise on low-poly meshes.
#pragma once

#include <type_traits>

#include "pipeline/shaders/specular.h"
#include "pipeline/shaders/technique_bindings.h"

namespace skinsim::pipeline::shaders {

// fwidth() of a varying: |dFdx| + |dFdy|. In count mode dFdx and dFdy are recorded as one
// ALU op each (the USSE derives them from neighbouring pixels of the 2x2 quad).
template <class L>
typename L::vec3 fwidth3(const typename L::FragIn& in, int slot) {
  if constexpr (L::kExecutes) {
    const auto d = in.direction(slot);
    return sl::abs(d.ddx) + sl::abs(d.ddy);
  } else if constexpr (std::is_same_v<L, sim::Emit>) {
    const auto v = in.direction(slot).value;
    return sl::abs(sl::dFdx(v)) + sl::abs(sl::dFdy(v));
  } else {
    const auto v = in.direction(slot).value;
    const auto ddx = v - v;
    const auto ddy = v - v;
    return sl::abs(ddx) + sl::abs(ddy);
  }
}

// Curvature as the LUT's v coordinate from screen-space derivatives:
// length(fwidth(N)) / length(fwidth(P)) (1/world unit) times `scale`.
template <class L>
typename L::f32 derivative_curvature(const typename L::FragIn& in, float scale) {
  using f32 = typename L::f32;
  const f32 dn = sl::length(fwidth3<L>(in, SurfaceSlots::kNormal));
  const f32 dp = sl::length(fwidth3<L>(in, SurfaceSlots::kWorldPos));
  return dn * sl::rcp(sl::max(dp, 1e-6f)) * scale;
}

// Penner's detail scattering for one light direction `l`: each channel's diffuse light from
// the (N.L, curvature) LUT with its own normal, red with the `blurred` one, green and blue
// blended from `sharp` towards it by f = saturate(1 - N_blur.L)^2 (0.3 + 0.7 f and f).
template <class L>
typename L::vec3 scattered_diffuse(typename L::TexUnit& tex, const typename L::vec3& sharp,
                                   const typename L::vec3& blurred, const typename L::vec3& l,
                                   const typename L::f32& curvature) {
  using vec2 = typename L::vec2;
  using vec3 = typename L::vec3;
  using vec4 = typename L::vec4;
  using f32 = typename L::f32;
  constexpr int kLut = TechniqueBindings::kPreintegratedLut;
  const f32 blur_n_dot_l = sl::dot(blurred, l);
  const f32 f0 = sl::saturate(1.0f - blur_n_dot_l);
  const f32 f = f0 * f0;
  const vec3 n_g = sl::normalize(sl::mix(sharp, blurred, f * 0.7f + 0.3f));
  const vec3 n_b = sl::normalize(sl::mix(sharp, blurred, f));
  // N.L in [-1, 1] -> u in [0, 1]; curvature row v (row 0 flat, at the top).
  const auto lut_u = [](const f32& n_dot_l) { return n_dot_l * 0.5f + 0.5f; };
  const vec4 red = tex.sample(kLut, vec2(lut_u(blur_n_dot_l), curvature));
  const vec4 green = tex.sample(kLut, vec2(lut_u(sl::dot(n_g, l)), curvature));
  const vec4 blue = tex.sample(kLut, vec2(lut_u(sl::dot(n_b, l)), curvature));
  return vec3(sl::x(red), sl::y(green), sl::z(blue));
}

template <GammaMode kGamma, SpecularModel kSpec, CurvatureSource kCurvature>
struct PreintegratedFS {
  static constexpr ShaderName kNameText = shader_name(
      {"preintegrated_fs", kCurvature == CurvatureSource::kDerivatives ? "_derivatives" : "",
       specular_suffix(kSpec), gamma_suffix(kGamma)});
  static constexpr const char* kName = kNameText.text;
  using Uniforms = TechniqueUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const SkinSurface<L> s = skin_surface<L, kGamma>(in, tex, u);
    f32 curvature(0.0f);  // LUT v coordinate: curvature / max curvature
    if constexpr (kCurvature == CurvatureSource::kVertex) {
      // The baked texture stores curvature / max curvature: the LUT v coordinate.
      curvature = sl::x(tex.sample(TechniqueBindings::kCurvature, in.texcoord(SurfaceSlots::kUv)));
    } else {
      curvature = derivative_curvature<L>(in, u.curvature_scale);
    }

    // The key light's visibility: through the penumbra-scattering LUT (Penner's shadow
    // scattering: the penumbra widened and reddened by the profile, one dependent read), or
    // tinted.
    vec3 key_vis = tinted<L>(s.visibility, u.lights);
    if (u.lights.shadows && u.shadow_scatter) {
      const f32 lut_u = s.visibility * u.shadow_lut_scale + u.shadow_lut_offset;
      key_vis = sl::xyz(tex.sample(LightBindings::kShadowLut, vec2(lut_u, 0.5f)));
    }
    vec3 diffuse_light = vec3(u.lights.ambient) +
                         transmitted<L>(in, s.vertex_normal, u.lights, SurfaceSlots::kLight);
    for (int i = 0; i < u.lights.count; ++i) {
      const vec3 scattered = scattered_diffuse<L>(tex, s.normal, s.vertex_normal,
                                                  vec3(u.lights.direction[i]), curvature);
      diffuse_light = diffuse_light + light_radiance<L>(i, key_vis, u.lights) * scattered;
    }
    return skin_color<kGamma, kSpec, L>(s, tex, u, diffuse_light);
  }
};

}  // namespace skinsim::pipeline::shaders

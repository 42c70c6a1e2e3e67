// The specular models every skin shader can use (the `specular` knob; docs/skin-techniques.md
// section 2), on top of the per-pixel surface terms those shaders share (skin_surface.h).
// All four scale the microfacet lobe the same way as d'Eon & Luebke's KS_Skin_Specular
// (GPU Gems 3 ch. 14):
//   specular = light * N.L * rho_s * pi D * F(V.H) * Vis * reflectivity
// so rho_s = 0.18 means the same thing in each and only the lobe shape differs:
//   ks_lut   - the dual Kelemen/Szirmay-Kalos lobes, Fresnel and diffuse energy from the BRDF
//              LUT: one dependent read (what the GPU Pro 5 mobile pipeline does);
//   ks       - the same lobes in ALU: Beckmann D, Vis = 1 / (4 (V.H)^2) (Kelemen);
//   ggx      - one GGX lobe, alpha = Beckmann m of lobe 1 (the usual equivalence), with
//              the height-correlated Smith visibility in Hammon's approximation (GDC 2017);
//   dual_ggx - two GGX lobes mixed in D by the lobe weights; visibility from the average
//              alpha (the dual-lobe recipe of docs/skin-techniques.md).
// The analytic models use Schlick F(N.V) for the environment rim light and 1 - F(N.V) as
// the diffuse energy term (the LUT pre-integrates both over the lobes).
#pragma once

#include <array>

#include "pipeline/bake/brdf_lut_encoding.h"
#include "pipeline/shaders/skin_surface.h"

namespace skinsim::pipeline::shaders {

// Uniforms of the skin shaders: the mobile shader's (skin_uniforms.h) plus the analytic
// lobes and the technique knobs (each shader reads the ones it needs).
struct TechniqueUniforms : SkinUniforms {
  float lobe1_roughness = 0.3f;  // Beckmann m (GGX alpha)
  float lobe2_roughness = 0.6f;
  float f0 = 0.028f;              // skin, IOR ~1.4
  float wrap = 0.5f;              // wrap lighting amount
  float curvature_scale = 1.0f;   // derivative curvature (1/world unit) -> pre-integrated LUT v
  bool shadow_scatter = true;     // pre-integrated: Penner's penumbra scattering LUT
  float shadow_lut_scale = 1.0f;  // visibility -> LUT u (shadow_scatter_lut.h)
  float shadow_lut_offset = 0.0f;
};

// A shader name assembled at compile time from parts ("wrap_fs" "_ggx" "_srgb").
struct ShaderName {
  char text[64]{};
};
constexpr ShaderName shader_name(std::initializer_list<const char*> parts) {
  ShaderName n;
  int k = 0;
  for (const char* p : parts) {
    for (; *p != '\0' && k < 63; ++p) n.text[k++] = *p;
  }
  return n;
}
constexpr const char* specular_suffix(SpecularModel m) {
  switch (m) {
    case SpecularModel::kKsLut:
      return "";
    case SpecularModel::kKs:
      return "_ks";
    case SpecularModel::kGgx:
      return "_ggx";
    case SpecularModel::kDualGgx:
      return "_dual_ggx";
  }
  return "";
}
constexpr const char* gamma_suffix(GammaMode g) {
  return g == GammaMode::kSquare ? "" : "_srgb";
}

template <class L>
struct Reflection {
  typename L::vec3 light;          // the lights' specular + environment rim light
  typename L::f32 diffuse_energy;  // fraction of light entering the skin
};

namespace detail {
// pi * GGX D for alpha^2 = a2 (the pi cancels D's 1/pi, as P_H does for Beckmann).
template <class F>
F pi_ggx_d(const F& n_dot_h2, float a2) {
  const F t = n_dot_h2 * (a2 - 1.0f) + 1.0f;
  return a2 * sl::rcp(t * t);
}
// Height-correlated Smith G / (4 N.L N.V), Hammon's linear approximation.
template <class F>
F ggx_visibility(const F& n_dot_l, const F& n_dot_v, float alpha) {
  const F denom =
      n_dot_l * (n_dot_v * (1.0f - alpha) + alpha) + n_dot_v * (n_dot_l * (1.0f - alpha) + alpha);
  return 0.5f * sl::rcp(sl::max(denom, 1e-4f));
}
template <class F>
F schlick(float f0, const F& cos_theta) {
  const F k = 1.0f - cos_theta;
  const F k2 = k * k;
  return f0 + (1.0f - f0) * (k2 * k2 * k);
}
}  // namespace detail

// The microfacet lobes' reflected light from one light (`radiance` already shadowed),
// and, from the BRDF LUT read, the lobe-averaged Fresnel and diffuse energy at this N.V.
template <class L>
struct LobeLight {
  typename L::vec3 light;
  typename L::f32 fresnel;  // ks_lut only
  typename L::f32 energy;   // ks_lut only
};

template <SpecularModel kSpec, class L>
LobeLight<L> lobe_light(const SkinSurface<L>& s, typename L::TexUnit& tex,
                        const TechniqueUniforms& u, const typename L::vec3& l,
                        const typename L::vec3& radiance) {
  using vec2 = typename L::vec2;
  using vec3 = typename L::vec3;
  using f32 = typename L::f32;
  const vec3 half = sl::normalize(s.view + l);
  const f32 n_dot_h = sl::saturate(sl::dot(s.normal, half));
  const f32 n_dot_v = sl::saturate(sl::dot(s.normal, s.view));
  const f32 n_dot_l = sl::saturate(sl::dot(s.normal, l));
  LobeLight<L> r{vec3(0.0f), f32(0.0f), f32(0.0f)};
  if constexpr (kSpec == SpecularModel::kKsLut) {
    const auto lut = tex.sample_lod(SkinBindings::kBrdfLut, vec2(n_dot_h, n_dot_v), u.lut_lod);
    const f32 lobes = bake::decode_specular_lobe(sl::x(lut)) * u.lobe1_weight +
                      bake::decode_specular_lobe(sl::y(lut)) * u.lobe2_weight;
    r.light = radiance * (lobes * n_dot_l * u.specular_intensity * s.reflectivity);
    r.fresnel = bake::decode_fresnel(sl::z(lut));
    r.energy = bake::decode_diffuse_energy(sl::w(lut));
    return r;
  } else {
    const f32 v_dot_h = sl::max(sl::dot(s.view, half), 1e-3f);
    const f32 c2 = sl::max(n_dot_h * n_dot_h, 1e-4f);
    f32 lobe(0.0f);
    if constexpr (kSpec == SpecularModel::kKs) {
      // pi D_Beckmann = exp((c2 - 1) / (m^2 c2)) / (m^2 c2^2), Vis = 1 / (4 (V.H)^2).
      const f32 inv_c2 = sl::rcp(c2);
      const auto pi_beckmann = [&](float m) {
        const float m2 = m * m;
        return sl::exp((c2 - 1.0f) * inv_c2 * (1.0f / m2)) * inv_c2 * inv_c2 * (1.0f / m2);
      };
      const f32 pi_d = pi_beckmann(u.lobe1_roughness) * u.lobe1_weight +
                       pi_beckmann(u.lobe2_roughness) * u.lobe2_weight;
      lobe = pi_d * sl::rcp(v_dot_h * v_dot_h * 4.0f);
    } else if constexpr (kSpec == SpecularModel::kGgx) {
      const float a = u.lobe1_roughness;
      lobe = detail::pi_ggx_d(c2, a * a) * detail::ggx_visibility(n_dot_l, n_dot_v, a);
    } else {
      const float a1 = u.lobe1_roughness, a2 = u.lobe2_roughness;
      const f32 pi_d = detail::pi_ggx_d(c2, a1 * a1) * u.lobe1_weight +
                       detail::pi_ggx_d(c2, a2 * a2) * u.lobe2_weight;
      lobe = pi_d * detail::ggx_visibility(n_dot_l, n_dot_v, 0.5f * (a1 + a2));
    }
    const f32 f_h = detail::schlick(u.f0, v_dot_h);
    r.light = radiance * (lobe * f_h * n_dot_l * u.specular_intensity * s.reflectivity);
    return r;
  }
}

// Specular of every light (the key light's shadowed by the surface's visibility) plus the
// environment rim light, and the diffuse energy term.
template <SpecularModel kSpec, class L>
Reflection<L> skin_specular(const SkinSurface<L>& s, typename L::TexUnit& tex,
                            const TechniqueUniforms& u) {
  using vec3 = typename L::vec3;
  using f32 = typename L::f32;
  const LightUniforms& lights = u.lights;
  const LobeLight<L> key = lobe_light<kSpec, L>(s, tex, u, vec3(lights.direction[0]),
                                                light_radiance<L>(0, vec3(s.visibility), lights));
  Reflection<L> r;
  r.light = key.light;
  for (int i = 1; i < lights.count; ++i) {
    r.light =
        r.light +
        lobe_light<kSpec, L>(s, tex, u, vec3(lights.direction[i]), vec3(lights.radiance[i])).light;
  }
  f32 fresnel = key.fresnel;
  r.diffuse_energy = key.energy;
  if constexpr (kSpec != SpecularModel::kKsLut) {
    fresnel = detail::schlick(u.f0, sl::saturate(sl::dot(s.normal, s.view)));
    r.diffuse_energy = 1.0f - fresnel;
  }
  r.light = r.light + sl::xyz(s.environment) * (fresnel * s.reflectivity * u.environment_intensity);
  return r;
}

// What a skin shader returns once it has its diffuse light: that light times the albedo and
// the specular model's diffuse energy, plus the specular light, gamma-encoded, opaque.
template <GammaMode kGamma, SpecularModel kSpec, class L>
typename L::vec4 skin_color(const SkinSurface<L>& s, typename L::TexUnit& tex,
                            const TechniqueUniforms& u, const typename L::vec3& diffuse_light) {
  const Reflection<L> r = skin_specular<kSpec, L>(s, tex, u);
  const typename L::vec3 color = s.albedo * diffuse_light * r.diffuse_energy + r.light;
  return typename L::vec4(encode_gamma<kGamma>(color), 1.0f);
}

}  // namespace skinsim::pipeline::shaders

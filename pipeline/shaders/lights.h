// The direct light every lit shader sees: the key light (index 0, the only one that casts
// shadows), an optional back light, ambient, the key light's shadow map and transmission
// through thin parts. The vertex shaders put the shadow-map coordinates and the baked
// thickness in varyings (LightVaryings says where), so the shadow fetch is an independent
// read (PowerVR performance guidelines: coordinates straight from a varying).
//
// Shadows: percentage-closer filtering over `shadow_taps` shadow-sampler fetches on a
// square grid one texel apart; each fetch compares one texel (nearest) or, with a linear
// shadow sampler, the 2x2 footprint with hardware filtering of the results
// (EXT_shadow_samplers on iOS). Only the first tap uses the varying directly; the others
// add an offset, so they are dependent reads. A shadow tint (the URP skin article) leaves
// that much of each channel's light in full shadow: visibility = tint + (1 - tint) v.
//
// Transmission (Jimenez et al., "Real-Time Realistic Skin Translucency", IEEE CG&A 2010,
// as in HDRP's thick-object mode): light reaching the back of a part `s` mm thick comes
// through attenuated by the diffusion profile's transmittance T(s) = sum_i w_i
// exp(-s^2 / v_i) (the six Gaussians of d'Eon & Luebke, variances v_i in mm^2), spread by
// saturate(0.3 - N.L). Not shadowed: the part that casts the shadow is what light crosses.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "sim/shader_io.h"

namespace skinsim::pipeline::shaders {

namespace sl = sim::sl;

inline constexpr int kMaxLights = 2;           // key + back light
inline constexpr int kMaxShadowTaps = 16;      // a 4x4 grid of fetches
inline constexpr int kTransmittanceTerms = 6;  // the profile's Gaussians

struct LightBindings {
  static constexpr int kShadowMap = 6;  // depth texture with a shadow sampler
  static constexpr int kShadowLut = 7;  // pre-integrated penumbra scattering (preintegrated)
};

// Varying slots of the shadow coordinates (vec3: u, v, depth) and the thickness (mm) in the
// vertex shader that feeds a fragment shader.
struct LightVaryings {
  int shadow_coord = -1;
  int thickness = -1;
};

// The defaults of LightVertexUniforms and LightUniforms are what the default knobs give on
// the built-in scene (shadows with four fetches, a back light, transmission): the programs'
// default profiles in `skinsim shaders`. FrameLights sets every field for a frame.

// What a vertex shader needs to feed LightVaryings.
struct LightVertexUniforms {
  bool shadow_coord = true;
  glm::mat4 shadow_matrix{1.0f};      // world -> (u, v, depth) of the shadow map
  float shadow_normal_offset = 0.0f;  // world units along the normal (against shadow acne)
  bool thickness = true;
};

template <class L>
void write_light_varyings(const typename L::VertexIn& in, typename L::VertexOut& out,
                          const LightVertexUniforms& u, const typename L::vec3& p,
                          const typename L::vec3& n, const LightVaryings& slots) {
  using vec4 = typename L::vec4;
  if (u.shadow_coord) {
    const vec4 c = u.shadow_matrix * vec4(p + n * u.shadow_normal_offset, 1.0f);
    out.set(slots.shadow_coord, sl::xyz(c));
  }
  if (u.thickness) out.set(slots.thickness, in.thickness());
}

struct LightUniforms {
  int count = 2;  // 1: key light only; 2: key and back light
  std::array<glm::vec3, kMaxLights> direction{glm::vec3(0.0f, 0.0f, 1.0f),
                                              glm::vec3(0.0f, 0.0f, -1.0f)};  // towards the light
  std::array<glm::vec3, kMaxLights> radiance{glm::vec3(1.0f), glm::vec3(0.0f)};
  glm::vec3 ambient{0.0f};

  bool shadows = true;
  int shadow_taps = 4;
  std::array<glm::vec2, kMaxShadowTaps> shadow_offsets{};  // uv, tap 0 is (0, 0)
  bool shadow_tinted = false;
  glm::vec3 shadow_tint{0.0f};

  bool transmission = true;
  std::array<glm::vec3, kTransmittanceTerms> transmittance_weight{};
  std::array<float, kTransmittanceTerms> transmittance_inv_variance{};  // 1 / v_i, 1/mm^2
};

// Fraction of the key light that reaches the fragment (1 without shadows).
template <class L>
typename L::f32 key_visibility(const typename L::FragIn& in, typename L::TexUnit& tex,
                               const LightUniforms& u, const LightVaryings& slots) {
  using f32 = typename L::f32;
  using vec3 = typename L::vec3;
  if (!u.shadows) return f32(1.0f);
  f32 lit = tex.sample_shadow(LightBindings::kShadowMap, in.direction(slots.shadow_coord));
  if (u.shadow_taps == 1) return lit;
  const vec3 coord = in.v3(slots.shadow_coord);
  for (int i = 1; i < u.shadow_taps; ++i) {
    const glm::vec2 o = u.shadow_offsets[i];
    lit = lit + tex.sample_shadow(LightBindings::kShadowMap, coord + vec3(o.x, o.y, 0.0f));
  }
  return lit * (1.0f / static_cast<float>(u.shadow_taps));
}

// Per-channel visibility after the shadow tint.
template <class L>
typename L::vec3 tinted(const typename L::f32& visibility, const LightUniforms& u) {
  using vec3 = typename L::vec3;
  if (!u.shadow_tinted) return vec3(visibility);
  return vec3(u.shadow_tint) + vec3(1.0f - u.shadow_tint) * visibility;
}

// Light i's radiance, the key light's times its visibility.
template <class L>
typename L::vec3 light_radiance(int i, const typename L::vec3& key_visibility,
                                const LightUniforms& u) {
  using vec3 = typename L::vec3;
  if (i == 0 && u.shadows) return vec3(u.radiance[0]) * key_visibility;
  return vec3(u.radiance[i]);
}

// Sum over the lights of radiance x saturate(N.L), plus ambient: what the irradiance
// passes store and the single-pass shaders' Lambert term.
template <class L>
typename L::vec3 lambert_irradiance(const typename L::vec3& n, const typename L::vec3& key_vis,
                                    const LightUniforms& u) {
  using vec3 = typename L::vec3;
  vec3 e(u.ambient);
  for (int i = 0; i < u.count; ++i) {
    e = e + light_radiance<L>(i, key_vis, u) * sl::saturate(sl::dot(n, vec3(u.direction[i])));
  }
  return e;
}

// Light transmitted through the part at this fragment (0 when transmission is off).
template <class L>
typename L::vec3 transmitted(const typename L::FragIn& in, const typename L::vec3& n,
                             const LightUniforms& u, const LightVaryings& slots) {
  using vec3 = typename L::vec3;
  if (!u.transmission) return vec3(0.0f);
  const auto s = in.f(slots.thickness);
  const auto s2 = s * s;
  vec3 t(0.0f);
  for (int i = 0; i < kTransmittanceTerms; ++i) {
    t = t + vec3(u.transmittance_weight[i]) * sl::exp(s2 * -u.transmittance_inv_variance[i]);
  }
  vec3 back(0.0f);
  for (int i = 0; i < u.count; ++i) {
    back = back + vec3(u.radiance[i]) * sl::saturate(0.3f - sl::dot(n, vec3(u.direction[i])));
  }
  return t * back;
}

}  // namespace skinsim::pipeline::shaders

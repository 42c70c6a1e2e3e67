// How the BRDF LUT's texels encode their values, and how a shader decodes them
// (docs/luts.md). Header-only so shaders and the baker share one definition.
//
// A shader samples the LUT at (N.H, N.V) with LOD = brdf_lut_lod(roughness scale) and lights a
// skin pixel with
//   specular = light * saturate(N.L) * rho_s * (w1 * decode_specular_lobe(R)
//                                              + w2 * decode_specular_lobe(G))
//   rim      = environment * decode_fresnel(B) * reflectivity
//   diffuse  = albedo * irradiance * decode_diffuse_energy(A)
#pragma once

#include <algorithm>
#include <cmath>

namespace skinsim::bake {

// R and G hold a lobe response s >= 0 as texel = (s / kSpecularEncodeRange)^(1/4), clamped to
// 1. The fourth root spreads 8-bit precision evenly in relative terms (about 8% per step at
// the skin's normal-incidence peak s ~ 0.08, 2% at s ~ 24) and decoding costs two multiplies
// (no transcendental). Responses above the range (a highlight seen within ~8 degrees of
// grazing) clip.
inline constexpr float kSpecularEncodeRange = 64.0f;

inline float encode_specular_lobe(float response) {
  return std::min(1.0f, std::sqrt(std::sqrt(std::max(0.0f, response) / kSpecularEncodeRange)));
}

template <class F>
F decode_specular_lobe(const F& texel) {
  const F t2 = texel * texel;
  return t2 * t2 * kSpecularEncodeRange;
}

// B is the lobe-averaged Fresnel reflectance for this N.V, stored as is.
template <class F>
F decode_fresnel(const F& texel) {
  return texel;
}

// A is the fraction of light that enters the skin (1 - specular directional albedo), as is.
template <class F>
F decode_diffuse_energy(const F& texel) {
  return texel;
}

// Roughness along the mip chain: level k holds lobes of roughness m * (1 + kMipRoughnessStep k),
// so the LOD that gives a roughness scale `scale` >= 1 is (scale - 1) / kMipRoughnessStep.
inline constexpr float kMipRoughnessStep = 0.5f;

constexpr float roughness_scale_for_level(int level) {
  return 1.0f + kMipRoughnessStep * static_cast<float>(level);
}

constexpr float brdf_lut_lod(float roughness_scale) {
  return (roughness_scale - 1.0f) / kMipRoughnessStep;
}

}  // namespace skinsim::bake

// Float reference functions of the specular models (docs/skin-techniques.md section 2), shared
// by the reference renderer and the LUT bakers. Vectors are unit length; cosines are dot
// products with the normal N unless named otherwise.
#pragma once

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>

namespace skinsim::bake {

// Beckmann distribution D(h) = exp(-tan^2(a) / m^2) / (pi m^2 cos^4(a)), a = angle(N, H),
// normalised so that int D(h) (N.H) dw_h = 1 over the hemisphere. 0 below the horizon.
inline float beckmann_d(float n_dot_h, float m) {
  if (n_dot_h <= 0.0f) return 0.0f;
  const float c2 = n_dot_h * n_dot_h;
  const float m2 = m * m;
  return std::exp((c2 - 1.0f) / (m2 * c2)) / (std::numbers::pi_v<float> * m2 * c2 * c2);
}

// Schlick's Fresnel approximation F = F0 + (1 - F0)(1 - cos)^5.
inline float fresnel_schlick(float f0, float cos_theta) {
  const float k = 1.0f - cos_theta;
  const float k2 = k * k;
  return f0 + (1.0f - f0) * (k2 * k2 * k);
}

// GGX / Trowbridge-Reitz D = a2 / (pi ((N.H)^2 (a2 - 1) + 1)^2) with a2 = roughness^4
// (roughness = perceptual roughness, alpha = roughness^2). 0 below the horizon.
inline float ggx_d(float n_dot_h, float roughness) {
  if (n_dot_h <= 0.0f) return 0.0f;
  const float a2 = roughness * roughness * roughness * roughness;
  const float t = n_dot_h * n_dot_h * (a2 - 1.0f) + 1.0f;
  return a2 / (std::numbers::pi_v<float> * t * t);
}

// One Kelemen/Szirmay-Kalos lobe as d'Eon & Luebke's KS_Skin_Specular (GPU Gems 3 ch. 14):
// P_H F / |h|^2 with h = L + V unnormalised, P_H = pi * beckmann_d (their PHBeckmann has no
// 1/pi) and F = Schlick at V.H. Since |h|^2 = 4 (V.H)^2 this is pi D F / (4 (V.H)^2):
// Kelemen's approximation of the geometry term G / (N.L N.V) by 1 / (V.H)^2, times pi.
// `v_dot_h` must be > 0.
inline float ks_lobe(float n_dot_h, float v_dot_h, float m, float f0) {
  return std::numbers::pi_v<float> * beckmann_d(n_dot_h, m) * fresnel_schlick(f0, v_dot_h) /
         (4.0f * v_dot_h * v_dot_h);
}

// KS_Skin_Specular(N, L, V, m, rho_s) of GPU Gems 3 ch. 14 with Schlick F0 (0.028 for skin):
// the reflected radiance factor N.L * rho_s * ks_lobe, or 0 when the light is below the
// surface. The pi of P_H makes rho_s = 0.18 the published skin value; with rho_s = 1/pi and
// F = 1 the lobe is the plain, energy-bounded Kelemen BRDF times N.L.
inline float ks_skin_specular(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v, float m,
                              float rho_s, float f0 = 0.028f) {
  const float n_dot_l = glm::dot(n, l);
  if (n_dot_l <= 0.0f) return 0.0f;
  const glm::vec3 h = l + v;
  const float h2 = glm::dot(h, h);
  if (h2 <= 0.0f) return 0.0f;  // L = -V: no half vector
  const glm::vec3 half = h / std::sqrt(h2);
  const float v_dot_h = glm::dot(v, half);
  return n_dot_l * rho_s * ks_lobe(glm::dot(n, half), v_dot_h, m, f0);
}

}  // namespace skinsim::bake

#include "pipeline/bake/dipole.h"

#include <glm/glm.hpp>
#include <numbers>

namespace skinsim::bake {

DipoleMedium jensen_skin1() {
  return {{0.032f, 0.17f, 0.48f}, {0.74f, 0.88f, 1.01f}, 1.3f};
}

DipoleMedium jensen_skin2() {
  return {{0.013f, 0.070f, 0.145f}, {1.09f, 1.59f, 1.79f}, 1.3f};
}

float diffuse_fresnel_reflectance(float eta) {
  return -1.440f / (eta * eta) + 0.710f / eta + 0.668f + 0.0636f * eta;
}

DipoleTerms dipole_terms(const DipoleMedium& m) {
  const glm::vec3 sigma_t = m.sigma_a + m.sigma_s_prime;
  const float f_dr = diffuse_fresnel_reflectance(m.eta);
  DipoleTerms t;
  t.boundary_a = (1.0f + f_dr) / (1.0f - f_dr);
  t.sigma_tr = glm::sqrt(3.0f * m.sigma_a * sigma_t);
  t.alpha_prime = m.sigma_s_prime / sigma_t;
  t.z_real = 1.0f / sigma_t;
  t.z_virtual = t.z_real * (1.0f + 4.0f * t.boundary_a / 3.0f);
  return t;
}

glm::vec3 dipole_rd(const DipoleTerms& t, float r_mm) {
  const auto pole = [&](const glm::vec3& z) {
    const glm::vec3 d = glm::sqrt(r_mm * r_mm + z * z);
    return z * (1.0f + t.sigma_tr * d) * glm::exp(-t.sigma_tr * d) / (d * d * d);
  };
  return t.alpha_prime / (4.0f * std::numbers::pi_v<float>)*(pole(t.z_real) + pole(t.z_virtual));
}

glm::vec3 dipole_total_rd(const DipoleTerms& t) {
  return 0.5f * t.alpha_prime *
         (glm::exp(-t.sigma_tr * t.z_real) + glm::exp(-t.sigma_tr * t.z_virtual));
}

glm::vec3 dipole_cdf(const DipoleTerms& t, float r_mm) {
  const auto outside = [&](const glm::vec3& z) {
    const glm::vec3 d = glm::sqrt(r_mm * r_mm + z * z);
    return z * glm::exp(-t.sigma_tr * d) / d;
  };
  const glm::vec3 all = glm::exp(-t.sigma_tr * t.z_real) + glm::exp(-t.sigma_tr * t.z_virtual);
  return 1.0f - (outside(t.z_real) + outside(t.z_virtual)) / all;
}

float dipole_mean_radius(const DipoleTerms& t, float u) {
  const auto mean_cdf = [&](float r) {
    const glm::vec3 c = dipole_cdf(t, r);
    return (c.r + c.g + c.b) / 3.0f;
  };
  // Bisection: the CDF rises monotonically from 0 at r = 0.
  float lo = 0.0f, hi = 1.0f;
  while (mean_cdf(hi) < u) hi *= 2.0f;
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (mean_cdf(mid) < u ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}

}  // namespace skinsim::bake

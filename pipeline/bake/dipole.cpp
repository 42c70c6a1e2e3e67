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
  const float inv_4pi = 0.25f / std::numbers::pi_v<float>;
  return inv_4pi * t.alpha_prime * (pole(t.z_real) + pole(t.z_virtual));
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

namespace {
// Where a monotonically decreasing f crosses `value` within [lo, hi], by bisection.
template <class F>
float decreasing_crossing(const F& f, float value, float lo, float hi) {
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (f(mid) > value ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}
}  // namespace

float dipole_mean_radius(const DipoleTerms& t, float u) {
  const auto mean_outside = [&](float r) {
    const glm::vec3 c = dipole_cdf(t, r);
    return 1.0f - (c.r + c.g + c.b) / 3.0f;
  };
  float hi = 1.0f;
  while (mean_outside(hi) > 1.0f - u) hi *= 2.0f;
  return decreasing_crossing(mean_outside, 1.0f - u, 0.0f, hi);
}

float dipole_mean_density(const DipoleTerms& t, float r_mm) {
  const glm::vec3 d = dipole_rd(t, r_mm) / dipole_total_rd(t);
  return (d.r + d.g + d.b) / 3.0f;
}

float dipole_ring_radius(const DipoleTerms& t, float u0, float u1) {
  const float inner = dipole_mean_radius(t, u0), outer = dipole_mean_radius(t, u1);
  const float average = (u1 - u0) / (std::numbers::pi_v<float> * (outer * outer - inner * inner));
  return decreasing_crossing([&](float r) { return dipole_mean_density(t, r); }, average, inner,
                             outer);
}

}  // namespace skinsim::bake

#include "pipeline/bake/skin_profile.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace skinsim::bake {

const std::array<GaussianTerm, 6>& skin_gaussians() {
  // d'Eon & Luebke, GPU Gems 3 ch. 14, the six-Gaussian skin fit: variance (mm^2), RGB weights.
  static const std::array<GaussianTerm, 6> kTerms{{
      {0.0064f, {0.233f, 0.455f, 0.649f}},
      {0.0484f, {0.100f, 0.336f, 0.344f}},
      {0.187f, {0.118f, 0.198f, 0.000f}},
      {0.567f, {0.113f, 0.007f, 0.007f}},
      {1.99f, {0.358f, 0.004f, 0.000f}},
      {7.41f, {0.078f, 0.000f, 0.000f}},
  }};
  return kTerms;
}

float gaussian_2d(float variance_mm2, float r_mm) {
  const double v = variance_mm2;
  const double r = r_mm;
  return static_cast<float>(std::exp(-r * r / (2.0 * v)) / (2.0 * std::numbers::pi * v));
}

glm::vec3 skin_profile(float r_mm) {
  glm::vec3 sum(0.0f);
  for (const GaussianTerm& term : skin_gaussians()) {
    sum += term.weight * gaussian_2d(term.variance_mm2, r_mm);
  }
  return sum;
}

float burley_profile(float r_mm, float d_mm) {
  const double s = 1.0 / d_mm;
  const double r = r_mm;
  return static_cast<float>(s * (std::exp(-s * r) + std::exp(-s * r / 3.0)) /
                            (8.0 * std::numbers::pi * r));
}

glm::vec3 burley_profile(float r_mm, const glm::vec3& d_mm) {
  return {burley_profile(r_mm, d_mm.r), burley_profile(r_mm, d_mm.g), burley_profile(r_mm, d_mm.b)};
}

float burley_cdf(float r_mm, float d_mm) {
  const double sr = static_cast<double>(r_mm) / d_mm;
  return static_cast<float>(1.0 - 0.25 * std::exp(-sr) - 0.75 * std::exp(-sr / 3.0));
}

float burley_sample_radius(float u, float d_mm) {
  if (u >= 1.0f) return std::numeric_limits<float>::infinity();
  // x^3 + 3x - 4(1 - u) = 0 has the single real root x = c - 1/c, c = cbrt(g + sqrt(g^2 + 1)),
  // g = 2(1 - u); then r = -3 d ln(x).
  const double g = 2.0 * (1.0 - static_cast<double>(u));
  const double c = std::cbrt(g + std::sqrt(g * g + 1.0));
  const double x = c - 1.0 / c;
  return static_cast<float>(-3.0 * d_mm * std::log(x));
}

}  // namespace skinsim::bake

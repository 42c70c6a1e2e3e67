#include "pipeline/bake/specular.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "pipeline/bake/hemisphere.h"

namespace skinsim::bake {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Hemisphere, IntegratesAnalyticCases) {
  const auto one = [](const glm::dvec3&) { return 1.0; };
  const auto cosine = [](const glm::dvec3& w) { return w.z; };
  EXPECT_NEAR(integrate_hemisphere(one, 96, 48, false), 2.0 * kPi, 1e-3);
  EXPECT_NEAR(integrate_hemisphere(cosine, 96, 48, false), kPi, 1e-3);
  EXPECT_NEAR(integrate_hemisphere(cosine, 96, 24, true), kPi, 1e-3);
  // By symmetry x^2, y^2 and z^2 each integrate to a third of 2 pi.
  const auto x_squared = [](const glm::dvec3& w) { return w.x * w.x; };
  EXPECT_NEAR(integrate_hemisphere(x_squared, 96, 48, false), 2.0 * kPi / 3.0, 1e-3);
}

TEST(Beckmann, ProjectedAreaIntegratesToOne) {
  for (float m : {0.05f, 0.1f, 0.3f, 0.6f, 1.0f, 2.0f}) {
    const double integral = integrate_hemisphere(
        [m](const glm::dvec3& h) { return beckmann_d(static_cast<float>(h.z), m) * h.z; }, 128, 32,
        false);
    EXPECT_NEAR(integral, 1.0, 2e-3) << "m = " << m;
  }
}

TEST(Beckmann, MatchesTheClosedForm) {
  const float m = 0.3f;
  const float alpha = 0.4f;  // angle between N and H
  const double expected = std::exp(-std::pow(std::tan(alpha), 2) / (m * m)) /
                          (kPi * m * m * std::pow(std::cos(alpha), 4));
  EXPECT_NEAR(beckmann_d(std::cos(alpha), m), expected, 1e-5 * expected);
  EXPECT_EQ(beckmann_d(0.0f, m), 0.0f);
  EXPECT_EQ(beckmann_d(-0.5f, m), 0.0f);
}

TEST(Ggx, ProjectedAreaIntegratesToOne) {
  for (float roughness : {0.3f, 0.5f, 0.8f, 1.0f}) {
    const double integral = integrate_hemisphere(
        [roughness](const glm::dvec3& h) {
          return ggx_d(static_cast<float>(h.z), roughness) * h.z;
        },
        256, 16, false);
    EXPECT_NEAR(integral, 1.0, 5e-3) << "roughness = " << roughness;
  }
}

TEST(Fresnel, SchlickLimits) {
  EXPECT_FLOAT_EQ(fresnel_schlick(0.028f, 1.0f), 0.028f);
  EXPECT_FLOAT_EQ(fresnel_schlick(0.028f, 0.0f), 1.0f);
  EXPECT_NEAR(fresnel_schlick(0.028f, 0.5f), 0.028f + 0.972f / 32.0f, 1e-6f);
}

TEST(KsSkinSpecular, MatchesGpuGemsFormulation) {
  // GPU Gems 3 ch. 14: N.L * rho_s * PH * F / dot(h, h), h = L + V unnormalised,
  // PH = exp(-tan^2 / m^2) / (m^2 cos^4) (no 1/pi), F = Schlick at V.H.
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  const glm::vec3 l = glm::normalize(glm::vec3(0.3f, 0.2f, 0.9f));
  const glm::vec3 v = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.7f));
  const float m = 0.3f;
  const glm::vec3 h = l + v;
  const glm::vec3 hn = glm::normalize(h);
  const double ndoth = glm::dot(n, hn);
  const double ta = std::tan(std::acos(ndoth));
  const double ph = std::exp(-ta * ta / (m * m)) / (m * m * std::pow(ndoth, 4));
  const double f = 0.028 + 0.972 * std::pow(1.0 - glm::dot(v, hn), 5);
  const double expected = glm::dot(n, l) * 0.18 * ph * f / glm::dot(h, h);
  EXPECT_NEAR(ks_skin_specular(n, l, v, m, 0.18f), expected, 1e-4 * expected);
  EXPECT_EQ(ks_skin_specular(n, -l, v, m, 0.18f), 0.0f);  // light below the surface
}

}  // namespace
}  // namespace skinsim::bake

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pipeline/bake/skin_profile.h"

namespace skinsim::bake {
namespace {

// int_0^max R(r) 2 pi r dr by the midpoint rule.
template <typename F>
double radial_integral(const F& profile, double max_r, int samples) {
  const double dr = max_r / samples;
  double sum = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double r = (i + 0.5) * dr;
    sum += profile(static_cast<float>(r)) * 2.0 * std::numbers::pi * r * dr;
  }
  return sum;
}

TEST(SkinProfile, WeightsOfEachColourSumToOne) {
  glm::dvec3 sum(0.0);
  for (const GaussianTerm& term : skin_gaussians()) sum += glm::dvec3(term.weight);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1.0, 0.002) << "channel " << c;
}

TEST(SkinProfile, EachGaussianIntegratesToOneOverThePlane) {
  for (const GaussianTerm& term : skin_gaussians()) {
    const double sigma = std::sqrt(term.variance_mm2);
    const double integral = radial_integral(
        [&](float r) { return gaussian_2d(term.variance_mm2, r); }, 10.0 * sigma, 20000);
    EXPECT_NEAR(integral, 1.0, 1e-4) << "variance " << term.variance_mm2;
  }
}

TEST(SkinProfile, EachColumnIntegratesToItsWeightSum) {
  for (int c = 0; c < 3; ++c) {
    double weights = 0.0;
    for (const GaussianTerm& term : skin_gaussians()) weights += term.weight[c];
    const double integral =
        radial_integral([c](float r) { return skin_profile(r)[c]; }, 30.0, 200000);
    EXPECT_NEAR(integral, weights, 1e-3) << "channel " << c;
    EXPECT_NEAR(integral, 1.0, 3e-3) << "channel " << c;
  }
}

TEST(SkinProfile, RedScattersFarthest) {
  const glm::vec3 far = skin_profile(2.0f);
  EXPECT_GT(far.r, 10.0f * far.g);
  EXPECT_GT(far.g, far.b);
}

TEST(Burley, IntegratesToOneOverThePlane) {
  for (float d : {0.3f, 1.0f, 3.0f}) {
    const double integral =
        radial_integral([d](float r) { return burley_profile(r, d); }, 60.0 * d, 200000);
    EXPECT_NEAR(integral, 1.0, 1e-4) << "d = " << d;
  }
}

TEST(Burley, VectorFormIsPerChannel) {
  const glm::vec3 d(1.0f, 0.5f, 0.25f);
  const glm::vec3 r = burley_profile(0.7f, d);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(r[c], burley_profile(0.7f, d[c]));
}

TEST(Burley, CdfIsTheIntegralOfTheProfile) {
  const float d = 0.8f;
  EXPECT_NEAR(burley_cdf(0.0f, d), 0.0f, 1e-7);
  EXPECT_NEAR(burley_cdf(100.0f, d), 1.0f, 1e-6);
  for (float r : {0.05f, 0.5f, 2.0f, 5.0f}) {
    const double partial =
        radial_integral([d](float x) { return burley_profile(x, d); }, r, 100000);
    EXPECT_NEAR(burley_cdf(r, d), partial, 1e-4) << "r = " << r;
  }
}

TEST(Burley, InverseCdfInvertsTheCdf) {
  for (float d : {0.2f, 1.0f, 4.0f}) {
    for (float r : {0.001f, 0.01f, 0.3f, 1.0f, 3.0f, 10.0f}) {
      const float rr = r * d;
      EXPECT_NEAR(burley_sample_radius(burley_cdf(rr, d), d), rr, 1e-3f * rr + 1e-5f)
          << "d = " << d << ", r = " << rr;
    }
    for (float u : {0.0f, 0.1f, 0.5f, 0.9f, 0.999f}) {
      EXPECT_NEAR(burley_cdf(burley_sample_radius(u, d), d), u, 1e-5f) << "u = " << u;
    }
  }
  EXPECT_EQ(burley_sample_radius(0.0f, 1.0f), 0.0f);
  EXPECT_TRUE(std::isinf(burley_sample_radius(1.0f, 1.0f)));
}

}  // namespace
}  // namespace skinsim::bake

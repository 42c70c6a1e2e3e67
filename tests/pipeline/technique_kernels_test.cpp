// The tables the diffusion techniques bake: energy conservation (weights sum to 1 per
// channel), the profile's known properties, and the curvature estimate on a sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/epsilon.hpp>
#include <numbers>

#include "pipeline/bake/skin_profile.h"
#include "pipeline/techniques/kernels.h"
#include "pipeline/techniques/uv_layout.h"

namespace skinsim::pipeline {
namespace {

template <class Weights>
glm::vec3 sum(const Weights& w) {
  glm::vec3 s(0.0f);
  for (const glm::vec3& v : w) s += v;
  return s;
}

void expect_unit(const glm::vec3& v) {
  EXPECT_NEAR(v.r, 1.0f, 1e-5f);
  EXPECT_NEAR(v.g, 1.0f, 1e-5f);
  EXPECT_NEAR(v.b, 1.0f, 1e-5f);
}

TEST(BurleyKernel, FitKeepsRedWidestAndMatchesMeanRadius) {
  const glm::vec3 d = burley_distance_fit();
  EXPECT_GT(d.r, d.g);
  EXPECT_GT(d.g, d.b);
  // Red's mean radius, from the table: sum w sqrt(v) sqrt(pi/2) = 1.12 mm -> d = 0.448 mm.
  EXPECT_NEAR(d.r, 0.448f, 0.01f);
}

TEST(BurleyKernel, WeightsConserveEnergyAndEstimateTheMeanRadius) {
  const glm::vec3 d(1.0f, 0.5f, 0.25f);
  const BurleyKernel k = burley_kernel(64, d);
  ASSERT_EQ(k.offsets_mm.size(), 64u);
  expect_unit(sum(k.weights));
  // The weighted mean tap radius estimates int r R_c(r) dA = 2.5 d_c.
  for (int c = 0; c < 3; ++c) {
    float mean = 0.0f;
    for (std::size_t i = 0; i < k.weights.size(); ++i) {
      mean += k.weights[i][c] * glm::length(k.offsets_mm[i]);
    }
    EXPECT_NEAR(mean, 2.5f * d[c], 0.15f * 2.5f * d[c]) << "channel " << c;
  }
  // The widest channel is sampled by its own pdf: equal weights.
  for (const glm::vec3& w : k.weights) EXPECT_NEAR(w.r, 1.0f / 64.0f, 1e-6f);
}

TEST(BurleyKernel, RadiiGrowAlongTheSpiral) {
  const BurleyKernel k = burley_kernel(16, burley_distance_fit());
  for (std::size_t i = 1; i < k.offsets_mm.size(); ++i) {
    EXPECT_GT(glm::length(k.offsets_mm[i]), glm::length(k.offsets_mm[i - 1]));
  }
}

TEST(DipoleKernel, CentreFirstRingsIntegrateTheProfile) {
  const bake::DipoleTerms t = bake::dipole_terms(bake::jensen_skin1());
  const DipoleKernel k = dipole_kernel(30, t);
  ASSERT_EQ(k.offsets_mm.size(), 30u);
  EXPECT_EQ(k.offsets_mm[0], glm::vec2(0.0f));
  const float reach = bake::dipole_mean_radius(t, kDipoleCoverage);
  for (std::size_t i = 1; i < k.offsets_mm.size(); ++i) {
    EXPECT_GT(glm::length(k.offsets_mm[i]), glm::length(k.offsets_mm[i - 1]));
    EXPECT_LT(glm::length(k.offsets_mm[i]), reach);
  }
  // As a quadrature: the mean normalised profile exactly (kDipoleCoverage of it), each
  // channel's total reflectance within 5% (one sample per ring).
  float mean = 0.0f;
  glm::vec3 total(0.0f);
  for (std::size_t i = 0; i < k.offsets_mm.size(); ++i) {
    const float r = glm::length(k.offsets_mm[i]);
    mean += bake::dipole_mean_density(t, r) * k.areas_mm2[i];
    total += bake::dipole_rd(t, r) * k.areas_mm2[i];
  }
  EXPECT_NEAR(mean, kDipoleCoverage, 1e-3f);
  const glm::vec3 exact = bake::dipole_total_rd(t);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c], exact[c], 0.05f * exact[c]) << c;
}

TEST(SeparableKernel, CentreFirstSymmetricAndNormalised) {
  const SeparableKernel k = separable_kernel();
  EXPECT_EQ(k.offsets_mm[0], 0.0f);
  expect_unit(sum(k.weights));
  // Red scatters farthest: its centre weight is the smallest share.
  EXPECT_LT(k.weights[0].r, k.weights[0].g);
  EXPECT_LT(k.weights[0].g, k.weights[0].b + 1e-6f);
  // Taps come in +-pairs with equal weights; the outermost is the range.
  float max_offset = 0.0f;
  for (int i = 1; i < shaders::kSsssTaps; ++i) {
    max_offset = std::max(max_offset, std::fabs(k.offsets_mm[i]));
    bool mirrored = false;
    for (int j = 1; j < shaders::kSsssTaps; ++j) {
      if (std::fabs(k.offsets_mm[j] + k.offsets_mm[i]) < 1e-5f) {
        mirrored = glm::all(glm::epsilonEqual(k.weights[i], k.weights[j], 1e-6f));
      }
    }
    EXPECT_TRUE(mirrored) << "tap " << i;
  }
  EXPECT_FLOAT_EQ(max_offset, kSsssRangeMm);
}

TEST(TextureSpaceKernel, IncrementalBlursComposeToEachTermsVariance) {
  const TextureSpaceKernel k = texture_space_kernel();
  expect_unit(sum(k.weights));
  float variance = bake::skin_gaussians()[0].variance_mm2;
  for (int i = 1; i < shaders::kTextureSpaceTerms; ++i) {
    variance += k.blur_sigma_mm[i] * k.blur_sigma_mm[i];
    EXPECT_NEAR(variance, bake::skin_gaussians()[i].variance_mm2, 1e-4f);
  }
}

// A UV sphere of radius r (mm units: units_per_mm = 1) has curvature 1/r everywhere.
scene::Mesh sphere(float radius, int rings, int segments) {
  scene::Mesh m;
  for (int i = 0; i <= rings; ++i) {
    const float theta = std::numbers::pi_v<float> * static_cast<float>(i) / rings;
    for (int j = 0; j <= segments; ++j) {
      const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(j) / segments;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      m.positions.push_back(n * radius);
      m.normals.push_back(n);
      m.uvs.emplace_back(static_cast<float>(j) / segments, static_cast<float>(i) / rings);
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const std::uint32_t a = i * (segments + 1) + j, b = a + segments + 1;
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return m;
}

TEST(VertexCurvature, SphereIsOneOverRadius) {
  for (const float radius : {5.0f, 20.0f}) {
    const std::vector<float> k = vertex_curvature(sphere(radius, 24, 48), 1.0f, 4);
    // Away from the poles (degenerate edges there).
    for (std::size_t i = 49 * 4; i < k.size() - 49 * 4; ++i) {
      EXPECT_NEAR(k[i], 1.0f / radius, 0.05f / radius) << "vertex " << i;
    }
  }
}

TEST(VertexCurvature, ScalesWithUnits) {
  // The same sphere in metres-per-unit... units_per_mm = 0.001: radius 0.02 units = 20 mm.
  const std::vector<float> k = vertex_curvature(sphere(0.02f, 24, 48), 0.001f, 0);
  EXPECT_NEAR(k[49 * 12], 1.0f / 20.0f, 0.05f / 20.0f);
}

}  // namespace
}  // namespace skinsim::pipeline

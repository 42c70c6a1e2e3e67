// The urp technique's terms at their limits (shaders/urp.h, shaders/ssao.h): the clear coat at
// strength 0, the dual lobes at equal roughness, the shadow-in-AO floor, the shadow tint at
// full light, and the SSAO pass over surfaces that occlude nothing.
#include <gtest/gtest.h>

#include <glm/gtc/epsilon.hpp>

#include "pipeline/frame.h"
#include "pipeline/shaders/urp.h"
#include "pipeline/techniques/screen_diffusion_passes.h"
#include "pipeline/techniques/urp/ssao_passes.h"
#include "sim/gpu.h"

namespace skinsim::pipeline {
namespace {

using shaders::SkinSurface;
using sim::Exec;

void expect_near(const glm::vec3& a, const glm::vec3& b, float eps) {
  EXPECT_TRUE(glm::all(glm::epsilonEqual(a, b, eps)))
      << a.x << "," << a.y << "," << a.z << " vs " << b.x << "," << b.y << "," << b.z;
}

// A lit point seen from several directions: (view, light) pairs around the normal +z.
std::vector<std::pair<glm::vec3, glm::vec3>> views_and_lights() {
  std::vector<std::pair<glm::vec3, glm::vec3>> out;
  for (const float a : {0.0f, 0.4f, 0.9f, 1.3f}) {
    for (const float b : {0.1f, 0.7f, 1.2f}) {
      out.emplace_back(glm::vec3(std::sin(a), 0.0f, std::cos(a)),
                       glm::normalize(glm::vec3(-std::sin(b), 0.3f, std::cos(b))));
    }
  }
  return out;
}

TEST(UrpTerms, ClearCoatOfStrengthZeroLeavesTheLayersBelow) {
  const glm::vec3 n(0.0f, 0.0f, 1.0f), below(0.3f, 0.2f, 0.1f), radiance(2.0f);
  for (const auto& [v, l] : views_and_lights()) {
    const glm::vec3 half = glm::normalize(v + l);
    const float f = shaders::clear_coat_fresnel(0.0f, glm::dot(v, half));
    const glm::vec3 coat = shaders::clear_coat_light<Exec>(n, v, l, half, radiance, 0.1f, f);
    EXPECT_EQ(shaders::under_clear_coat<Exec>(below, f, coat), below);
    // A coat of strength 1 takes at least its normal-incidence reflectance from below.
    const float full = shaders::clear_coat_fresnel(1.0f, glm::dot(v, half));
    EXPECT_GE(full, shaders::kClearCoatF0 - 1e-6f);
    EXPECT_LT(glm::length(below * (1.0f - full)), glm::length(below));
  }
}

TEST(UrpTerms, DualLobesOfEqualRoughnessAreOneLobe) {
  shaders::TechniqueUniforms u;
  u.lobe1_roughness = u.lobe2_roughness = 0.35f;
  u.lobe1_weight = 0.85f;
  u.lobe2_weight = 0.15f;
  sim::ExecTexUnit tex(nullptr, nullptr);  // the analytic lobes read no texture
  for (const auto& [v, l] : views_and_lights()) {
    SkinSurface<Exec> s{};
    s.normal = glm::vec3(0.0f, 0.0f, 1.0f);
    s.view = v;
    s.reflectivity = 0.8f;
    const glm::vec3 radiance(1.0f, 0.9f, 0.8f);
    const glm::vec3 dual =
        shaders::lobe_light<SpecularModel::kDualGgx, Exec>(s, tex, u, l, radiance).light;
    const glm::vec3 one =
        shaders::lobe_light<SpecularModel::kGgx, Exec>(s, tex, u, l, radiance).light;
    expect_near(dual, one, 1e-5f * std::max(1.0f, glm::length(one)));
  }
  // Image-based: the two lookups' weights at equal roughness add up to one lobe's.
  const auto a = shaders::environment_lobe(0.35f, 0.85f, u.f0);
  const auto b = shaders::environment_lobe(0.35f, 0.15f, u.f0);
  const auto whole = shaders::environment_lobe(0.35f, 1.0f, u.f0);
  for (const float g : {0.0f, 0.3f, 1.0f}) {
    EXPECT_NEAR(shaders::environment_brdf(u.f0, a, g) + shaders::environment_brdf(u.f0, b, g),
                shaders::environment_brdf(u.f0, whole, g), 1e-6f);
  }
}

TEST(UrpTerms, ShadowInAoKeepsTheArticlesFloor) {
  for (const float ao : {1.0f, 0.7f, 0.2f}) {
    EXPECT_FLOAT_EQ(shaders::shadow_in_ao(ao, 0.0f), ao * 0.35f);
    EXPECT_FLOAT_EQ(shaders::shadow_in_ao(ao, 0.2f), ao * 0.35f);
    EXPECT_FLOAT_EQ(shaders::shadow_in_ao(ao, 0.6f), ao * 0.6f);
    EXPECT_FLOAT_EQ(shaders::shadow_in_ao(ao, 1.0f), ao);
  }
}

TEST(UrpTerms, ShadowTintIsIdentityInFullLightAndDarkSkinInShadow) {
  EXPECT_EQ(shaders::shadow_tint<Exec>(1.0f), glm::vec3(1.0f));
  expect_near(shaders::shadow_tint<Exec>(0.0f), glm::vec3(0.11f, 0.025f, 0.012f), 1e-7f);
  // Brightened: above the linear map from the dark colour to white inside the penumbra.
  const glm::vec3 linear = glm::mix(shaders::kShadowSkinColor, glm::vec3(1.0f), 0.5f);
  EXPECT_TRUE(glm::all(glm::greaterThan(shaders::shadow_tint<Exec>(0.5f), linear)));
}

// The AO pass over a plane of depth d0 + a x + b y (mm; x right, y up) with its normal, in an
// orthographic view of 2 pixels per mm: every tap lies in the pixel's tangent plane.
sim::RenderTarget ssao_of_plane(float a, float b) {
  constexpr int kSize = 64;
  constexpr float kPixelsPerMm = 2.0f;
  sim::RenderTarget source("depth_normal", kSize, kSize, sim::TexelFormat::kRGBA16F);
  const glm::vec3 n = glm::normalize(glm::vec3(a, b, 1.0f));
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float x_mm = (static_cast<float>(x) + 0.5f) / kPixelsPerMm;
      const float y_mm = -(static_cast<float>(y) + 0.5f) / kPixelsPerMm;  // rows grow downwards
      source.at(x, y) =
          sim::quantize(glm::vec4(n, 100.0f + a * x_mm + b * y_mm), sim::TexelFormat::kRGBA16F);
    }
  }
  shaders::SsaoUniforms u = ssao_uniforms(PipelineConfig{}.urp.ssao_taps);
  u.focal_uv = glm::vec2(kPixelsPerMm / kSize);
  u.noise_uv = glm::vec2(0.06711056f * kSize, 0.00583715f * kSize);
  View view;
  view.orthographic = true;
  view.width = view.height = kSize;
  view.skin_rect = {0, 0, kSize, kSize};
  sim::RenderTarget ao("ssao", kSize, kSize, sim::TexelFormat::kRGBA8);
  sim::Gpu gpu(sim::GpuConfig{});
  kernel_pass("ssao", kernel_program<shaders::SsaoFSFor>(view, u), source, ao, view, gpu);
  return ao;
}

TEST(UrpSsao, UnoccludedTapsGiveOne) {
  // Taps reach kSsaoRadiusMm = 24 pixels: the centre 8 x 8 never reads past the edges.
  for (const auto& [a, b] : {std::pair{0.0f, 0.0f}, {0.6f, 0.0f}, {0.0f, -0.6f}, {0.4f, 0.5f}}) {
    const sim::RenderTarget ao = ssao_of_plane(a, b);
    for (int y = 28; y < 36; ++y) {
      for (int x = 28; x < 36; ++x) EXPECT_EQ(ao.at(x, y).r, 1.0f) << a << "," << b;
    }
  }
}

TEST(UrpSsao, ACreaseOccludes) {
  // A tap on a surface in front of the pixel's tangent plane occludes it.
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  EXPECT_GT(shaders::ssao_tap_occlusion<Exec>(glm::vec3(5.0f, 0.0f, 4.0f), n), 0.4f);
  EXPECT_EQ(shaders::ssao_tap_occlusion<Exec>(glm::vec3(5.0f, 0.0f, -4.0f), n), 0.0f);
  // The background (metres behind) does not.
  EXPECT_EQ(shaders::ssao_tap_occlusion<Exec>(glm::vec3(5.0f, 0.0f, 500.0f), n), 0.0f);
}

}  // namespace
}  // namespace skinsim::pipeline

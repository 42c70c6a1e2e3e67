#include "pipeline/techniques/kernels.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pipeline/bake/skin_profile.h"

namespace skinsim::pipeline {

namespace {
template <class Weights>
void normalise_per_channel(Weights& weights) {
  glm::vec3 total(0.0f);
  for (const glm::vec3& w : weights) total += w;
  for (glm::vec3& w : weights) w /= total;
}
}  // namespace

glm::vec3 burley_distance_fit() {
  glm::vec3 mean_radius(0.0f), total(0.0f);
  for (const bake::GaussianTerm& g : bake::skin_gaussians()) {
    mean_radius += g.weight * std::sqrt(g.variance_mm2) * std::sqrt(std::numbers::pi_v<float> / 2);
    total += g.weight;
  }
  return mean_radius / total / 2.5f;
}

BurleyKernel burley_kernel(int samples, const glm::vec3& d) {
  const float d_max = std::max({d.r, d.g, d.b});
  // Golden angle: successive taps fill the disc evenly whatever the count.
  const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
  BurleyKernel k;
  for (int i = 0; i < samples; ++i) {
    const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(samples);
    const float r = bake::burley_sample_radius(u, d_max);
    const float angle = golden * static_cast<float>(i);
    k.offsets_mm.emplace_back(r * std::cos(angle), r * std::sin(angle));
    k.weights.push_back(bake::burley_profile(r, d) / bake::burley_profile(r, d_max));
  }
  normalise_per_channel(k.weights);
  return k;
}

DipoleKernel dipole_kernel(int samples, const bake::DipoleTerms& terms) {
  const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
  const auto share = [&](int i) { return kDipoleCoverage * i / static_cast<float>(samples); };
  const auto disc = [&](int i) {
    const float r = bake::dipole_mean_radius(terms, share(i));
    return std::numbers::pi_v<float> * r * r;
  };
  DipoleKernel k;
  k.offsets_mm.emplace_back(0.0f, 0.0f);
  k.areas_mm2.push_back(share(1) / bake::dipole_mean_density(terms, 0.0f));
  for (int i = 1; i < samples; ++i) {
    const float r = bake::dipole_ring_radius(terms, share(i), share(i + 1));
    const float angle = golden * static_cast<float>(i);
    k.offsets_mm.emplace_back(r * std::cos(angle), r * std::sin(angle));
    k.areas_mm2.push_back(disc(i + 1) - disc(i));
  }
  return k;
}

SeparableKernel separable_kernel() {
  constexpr int n = shaders::kSsssTaps;
  std::array<float, n> offsets{};
  const float step = 2.0f / static_cast<float>(n - 1);
  for (int i = 0; i < n; ++i) {
    const float o = -1.0f + static_cast<float>(i) * step;
    offsets[i] = kSsssRangeMm * std::copysign(o * o, o);
  }
  const auto profile_1d = [](float x) {
    glm::vec3 sum(0.0f);
    for (const bake::GaussianTerm& g : bake::skin_gaussians()) {
      sum += g.weight * std::exp(-x * x / (2.0f * g.variance_mm2)) /
             std::sqrt(2.0f * std::numbers::pi_v<float> * g.variance_mm2);
    }
    return sum;
  };
  std::array<glm::vec3, n> weights{};
  for (int i = 0; i < n; ++i) {
    const float left = i > 0 ? offsets[i] - offsets[i - 1] : 0.0f;
    const float right = i < n - 1 ? offsets[i + 1] - offsets[i] : 0.0f;
    weights[i] = profile_1d(offsets[i]) * (0.5f * (left + right));
  }
  normalise_per_channel(weights);
  // Centre (offset 0, the middle tap) first, as the shader reads it.
  SeparableKernel k;
  const int centre = n / 2;
  k.offsets_mm[0] = 0.0f;
  k.weights[0] = weights[centre];
  int j = 1;
  for (int i = 0; i < n; ++i) {
    if (i == centre) continue;
    k.offsets_mm[j] = offsets[i];
    k.weights[j] = weights[i];
    ++j;
  }
  return k;
}

TextureSpaceKernel texture_space_kernel() {
  TextureSpaceKernel k;
  const auto& terms = bake::skin_gaussians();
  static_assert(std::tuple_size_v<std::decay_t<decltype(terms)>> == shaders::kTextureSpaceTerms);
  for (int i = 0; i < shaders::kTextureSpaceTerms; ++i) {
    k.weights[i] = terms[i].weight;
    k.blur_sigma_mm[i] =
        i == 0 ? 0.0f : std::sqrt(terms[i].variance_mm2 - terms[i - 1].variance_mm2);
  }
  normalise_per_channel(k.weights);
  return k;
}

}  // namespace skinsim::pipeline

#include "pipeline/bake/shadow_scatter_lut.h"

#include <algorithm>
#include <cmath>

#include "pipeline/bake/skin_profile.h"

namespace skinsim::bake {

std::vector<glm::vec3> shadow_scatter_lut(int width, float penumbra_mm) {
  const float w = std::max(penumbra_mm, 1e-3f);
  const auto ramp = [w](float x) { return std::clamp(x / w + 0.5f, 0.0f, 1.0f); };
  glm::vec3 weight_sum(0.0f);
  for (const GaussianTerm& g : skin_gaussians()) weight_sum += g.weight;
  std::vector<glm::vec3> lut(static_cast<std::size_t>(width));
  constexpr int kSteps = 256;  // per side, over +-4 sigma
  lut.front() = glm::vec3(0.0f);
  lut.back() = glm::vec3(1.0f);
  for (int i = 1; i + 1 < width; ++i) {
    const float s = static_cast<float>(i) / static_cast<float>(width - 1);
    const float x = (s - 0.5f) * w;
    glm::vec3 sum(0.0f);
    for (const GaussianTerm& g : skin_gaussians()) {
      const float sigma = std::sqrt(g.variance_mm2);
      const float dy = 4.0f * sigma / kSteps;
      float conv = 0.0f, norm = 0.0f;
      for (int k = -kSteps; k <= kSteps; ++k) {
        const float y = static_cast<float>(k) * dy;
        const float gy = std::exp(-0.5f * y * y / g.variance_mm2);
        conv += ramp(x - y) * gy;
        norm += gy;
      }
      sum += g.weight * (conv / norm);
    }
    lut[static_cast<std::size_t>(i)] = sum / weight_sum;
  }
  return lut;
}

}  // namespace skinsim::bake

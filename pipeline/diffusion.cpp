#include "pipeline/diffusion.h"

#include <cmath>

#include "pipeline/bake/skin_profile.h"

namespace skinsim::pipeline {

LayerSplit skin_layer_split(float narrow_variance_mm2) {
  glm::vec3 total(0.0f), wide(0.0f);
  float red_variance_sum = 0.0f;
  for (const bake::GaussianTerm& g : bake::skin_gaussians()) {
    total += g.weight;
    if (g.variance_mm2 <= narrow_variance_mm2) continue;
    wide += g.weight;
    red_variance_sum += g.weight.r * g.variance_mm2;
  }
  LayerSplit s;
  s.wide_fraction = wide / total;
  s.wide_sigma_mm = wide.r > 0.0f ? std::sqrt(red_variance_sum / wide.r) : 0.0f;
  return s;
}

}  // namespace skinsim::pipeline

// The reference's subsurface diffusion with the skin profile's six Gaussians (d'Eon and
// Luebke, GPU Gems 3 ch. 14; bake/skin_profile.h), the default reference_profile: per skin
// pixel p and Gaussian i, M_i(p) = sum_q G_i(|x_p - x_q|) E(q) / sum_q G_i(|x_p - x_q|) over
// the skin pixels q on a screen grid spanning +-3 sigma_i (projected at p's depth), and
// M = sum_i w_i M_i. The distance is between the two surface points in world space, so light
// does not bleed across depth discontinuities.
#pragma once

#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "pipeline/gpu_scene.h"
#include "pipeline/reference/skin_diffusion.h"
#include "sim/render_target.h"

namespace skinsim::pipeline {

class GaussianDiffusion final : public SkinDiffusion {
 public:
  // `position`: world position and material kind (kind == kind_skin marks skin);
  // `irradiance`: one value per pixel.
  GaussianDiffusion(const sim::RenderTarget& position, float kind_skin,
                    const std::vector<glm::vec3>& irradiance, const View& view, float units_per_mm);
  ~GaussianDiffusion() override;
  GaussianDiffusion(const GaussianDiffusion&) = delete;
  GaussianDiffusion& operator=(const GaussianDiffusion&) = delete;

  // A row at a time, so that pixels can share SIMD registers (the same bits as one pixel at
  // a time).
  void row(int y, int x_begin, int x_end, glm::vec3* out) const override;

 private:
  class Impl;
  std::unique_ptr<const Impl> impl_;
};

}  // namespace skinsim::pipeline

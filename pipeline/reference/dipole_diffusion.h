// The reference's subsurface diffusion with Jensen et al. 2001's dipole profile (Skin1,
// bake/dipole.h) instead of the six Gaussians (reference_profile = dipole): per pixel p,
// M(p) = sum_q R_d(|x_p - x_q|) A_q E(q) / sum_q R_d(|x_p - x_q|) A_q over skin pixels q on a
// polar grid around p: p itself for the innermost disc, then kRings - 1 rings, the disc cut
// into kRings shares of the channels' mean profile out to where it holds 99.9%
// (bake::dipole_mean_radius), kAngles samples per ring turned by the golden angle from ring
// to ring, projected at p's depth; A_q is the sample's share of its ring's area, and R_d is
// evaluated on the world-space distance between the two surface points (so, like the Gaussian
// reference, it does not bleed across depth discontinuities).
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "pipeline/bake/dipole.h"
#include "pipeline/gpu_scene.h"
#include "pipeline/reference/skin_diffusion.h"
#include "sim/render_target.h"

namespace skinsim::pipeline {

class DipoleDiffusion final : public SkinDiffusion {
 public:
  // `position`: world position and material kind (kind == kind_skin marks skin);
  // `irradiance`: one value per pixel.
  DipoleDiffusion(const sim::RenderTarget& position, float kind_skin,
                  const std::vector<glm::vec3>& irradiance, const View& view, float units_per_mm,
                  const bake::DipoleTerms& terms);
  void row(int y, int x_begin, int x_end, glm::vec3* out) const override;

  static constexpr int kRings = 48;
  static constexpr int kAngles = 16;

 private:
  glm::vec3 at(int x, int y) const;  // M at one skin pixel
  struct Sample {
    glm::vec2 offset_mm;  // in the image plane at p's depth
    float area_mm2;
  };
  glm::vec3 profile(float distance2_mm2) const;  // R_d from the table

  const sim::RenderTarget& position_;
  float kind_skin_;
  const std::vector<glm::vec3>& irradiance_;
  const View& view_;
  float units_per_mm_;
  std::vector<Sample> samples_;
  // R_d at squared distances i * table_step_ (mm^2), linearly interpolated; 0 beyond.
  std::vector<glm::vec3> table_;
  float table_step_ = 1.0f;
};

}  // namespace skinsim::pipeline

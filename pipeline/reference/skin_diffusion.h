// The reference's subsurface diffusion of the skin's irradiance, whichever profile
// (reference_profile): GaussianDiffusion (six Gaussians) or DipoleDiffusion (Jensen's dipole).
#pragma once

#include <glm/vec3.hpp>

namespace skinsim::pipeline {

class SkinDiffusion {
 public:
  virtual ~SkinDiffusion() = default;
  // The diffused irradiance M of the skin pixels of row y in [x_begin, x_end), to
  // out[x - x_begin]; the entries of other pixels are left as they are.
  virtual void row(int y, int x_begin, int x_end, glm::vec3* out) const = 0;
};

}  // namespace skinsim::pipeline

// How the mobile pipeline's single blur approximates the six-Gaussian skin profile
// (d'Eon & Luebke, GPU Gems 3): the profile's narrow Gaussians (below the threshold
// variance) stay in the sharp per-pixel light (epidermis), the wide ones are the blurred
// layer (subdermis). Per channel, the wide Gaussians' share of the weight is how much of
// that channel's light the blurred buffer supplies; their weight-averaged variance (red,
// which dominates) sets the blur width. Nothing here is tuned: it is read off the table.
#pragma once

#include <glm/glm.hpp>

namespace skinsim::pipeline {

struct LayerSplit {
  glm::vec3 wide_fraction{0.0f};  // per channel, in [0,1]
  float wide_sigma_mm = 0.0f;     // sqrt of red's weight-averaged wide variance
};

// Gaussians with variance <= 0.1 mm^2 (sigma ~0.3 mm) count as narrow: below a pixel at
// close-up framing on the target display.
constexpr float kNarrowVarianceMm2 = 0.1f;

LayerSplit skin_layer_split(float narrow_variance_mm2 = kNarrowVarianceMm2);

}  // namespace skinsim::pipeline

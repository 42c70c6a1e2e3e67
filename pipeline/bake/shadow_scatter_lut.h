// Penner's pre-integrated shadow scattering (GPU Pro 2, "Pre-Integrated Skin Shading",
// section "Shadow scattering"): a shadow-map penumbra `penumbra_mm` wide is a ramp of
// visibility across the surface; light diffusing under the skin blurs that ramp with the
// profile, widening the penumbra per channel (red furthest). The table maps the filtered
// visibility s to the scattered visibility per channel, assuming the ramp: s at position
// x = (s - 1/2) W across a penumbra of width W, scattered visibility
//   S_c(s) = sum_i w_ic int ramp(x - y) N(y; v_i) dy / sum_i w_ic
// with the 1D marginals N(.; v_i) of the profile's Gaussians (a 2D Gaussian's line
// marginal is the 1D Gaussian of the same variance). s = 0 and s = 1 also stand for points
// far from any penumbra, so the end entries are exactly 0 and 1 (fully shadowed, fully lit).
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace skinsim::bake {

// `width` (>= 2) entries for s = i / (width - 1): read at texture coordinate
// s (width - 1) / width + 1 / (2 width). Linear RGB in [0, 1].
std::vector<glm::vec3> shadow_scatter_lut(int width, float penumbra_mm);

}  // namespace skinsim::bake

// Diffusion profiles of skin: radial reflectance R(r) of light entering at distance r (mm),
// normalised so that its integral over the plane, int_0^inf R(r) 2 pi r dr, is about 1.
#pragma once

#include <array>
#include <glm/vec3.hpp>

namespace skinsim::bake {

// One Gaussian of the sum-of-Gaussians skin profile of d'Eon & Luebke (GPU Gems 3, ch. 14,
// table in docs/skin-techniques.md section 4).
struct GaussianTerm {
  float variance_mm2;
  glm::vec3 weight;  // R, G, B
};

// The six terms, narrowest first. Each colour's weights sum to about 1.
const std::array<GaussianTerm, 6>& skin_gaussians();

// The 2D-normalised Gaussian G(v, r) = exp(-r^2 / (2v)) / (2 pi v): integrates to 1 over the
// plane. (Some published bakers use the 1D factor 1 / sqrt(2 pi v) by mistake.)
float gaussian_2d(float variance_mm2, float r_mm);

// R(r) = sum_i w_i G(v_i, r), per colour channel, in 1/mm^2.
glm::vec3 skin_profile(float r_mm);

// Burley's normalised diffusion (Christensen & Burley 2015, "Approximate Reflectance Profiles
// for Efficient Subsurface Scattering"): R(r) = s (exp(-s r) + exp(-s r / 3)) / (8 pi r) with
// s = 1 / d, d the scattering distance in mm. Integrates to 1 over the plane; infinite at r = 0.
float burley_profile(float r_mm, float d_mm);
glm::vec3 burley_profile(float r_mm, const glm::vec3& d_mm);

// Fraction of the diffused light that comes out within radius r:
// CDF(r) = 1 - exp(-s r) / 4 - 3 exp(-s r / 3) / 4.
float burley_cdf(float r_mm, float d_mm);

// Inverse of burley_cdf for u in [0, 1): the radius to importance-sample for a uniform u.
// Closed form (Golubev 2018, "Efficient Screen-Space Subsurface Scattering Using Burley's
// Normalized Diffusion in Real-Time"): with x = exp(-s r / 3) the CDF is a cubic in x,
// x^3 + 3x - 4(1 - u) = 0, solved by Cardano's formula. Returns +infinity for u >= 1.
float burley_sample_radius(float u, float d_mm);

}  // namespace skinsim::bake

// The tables the diffusion techniques bake on the CPU and pass as uniforms: tap offsets
// and per-channel weights, each normalised so a channel's weights sum to 1 (energy
// conservation: a uniformly lit flat patch keeps its irradiance).
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "pipeline/bake/dipole.h"
#include "pipeline/shaders/screen_diffusion.h"
#include "pipeline/shaders/texture_space.h"

namespace skinsim::pipeline {

// Burley scattering distances fitted to the six-Gaussian profile: the same mean scattering
// radius per channel. Burley's mean radius is int r R(r) dA = 2.5 d; a 2D Gaussian's is
// sigma sqrt(pi / 2).
glm::vec3 burley_distance_fit();

// Importance-sampled Burley taps (Golubev 2018): radii from the inverse CDF of the widest
// channel at stratified u = (i + 0.5) / n, angles on a golden-angle spiral; weights
// R_c(r) / R_widest(r) (the estimator of the profile convolution), normalised per channel.
struct BurleyKernel {
  std::vector<glm::vec2> offsets_mm;
  std::vector<glm::vec3> weights;
};
BurleyKernel burley_kernel(int samples, const glm::vec3& distance_mm);

// The dipole's taps: the disc around the pixel cut into `samples` rings that hold equal
// shares of the mean of the three channels' normalised R_d (bake/dipole.h: red's long tail and
// blue's sharp core both get taps), out to where they hold kDipoleCoverage. Tap 0 is the
// centre, weighted so that R_d(0) times its weight is the innermost share; tap i sits in ring
// i at the radius where the mean profile equals its ring average
// (bake::dipole_ring_radius), at i golden angles, weighted by the ring's area. A fixed
// pattern (the shader turns it per pixel); the same for every thread count.
struct DipoleKernel {
  std::vector<glm::vec2> offsets_mm;
  std::vector<float> areas_mm2;  // the quadrature weight of each tap, mm^2
};
inline constexpr float kDipoleCoverage = 0.999f;
DipoleKernel dipole_kernel(int samples, const bake::DipoleTerms& terms);

// Jimenez's separable SSS kernel (SeparableSSS, 2015) fitted to the six-Gaussian profile:
// 1D offsets distributed as range * sign(o) * o^2 (dense near the centre), each weighted by
// the profile's 1D Gaussians times the tap's span; centre first.
struct SeparableKernel {
  std::array<float, shaders::kSsssTaps> offsets_mm{};
  std::array<glm::vec3, shaders::kSsssTaps> weights{};
};
// Half-width of the kernel in mm: 3 sigma of the profile's last large red term (variance
// 1.99 mm^2); the 7.41 mm^2 tail (weight 0.078) is truncated and its energy renormalised.
inline constexpr float kSsssRangeMm = 4.2f;
SeparableKernel separable_kernel();

// Texture-space diffusion: per-term combine weights (the profile's, normalised per channel)
// and the standard deviation in mm of each incremental blur (term i from term i - 1:
// variances add, so sigma_i = sqrt(v_i - v_{i-1})). Term 0 is the unblurred irradiance.
struct TextureSpaceKernel {
  std::array<glm::vec3, shaders::kTextureSpaceTerms> weights{};
  std::array<float, shaders::kTextureSpaceTerms> blur_sigma_mm{};  // [0] unused (0)
};
TextureSpaceKernel texture_space_kernel();

}  // namespace skinsim::pipeline

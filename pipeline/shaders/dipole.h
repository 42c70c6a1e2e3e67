// The dipole technique's kernel: Jensen et al. 2001's diffuse reflectance R_d(r) evaluated in
// the shader, per pixel and per tap, on the distance between the shaded point and each tap's
// surface point, over a fixed disc of taps around the pixel (techniques/kernels.h). As the
// Unity article does, the BSSRDF is evaluated, not tabulated: that is where its cost is.
//
// Each tap reads the `diffuse` buffer (irradiance, view distance in mm) at a screen offset of
// r_i mm at the centre's depth; the distance to its surface point is
// sqrt(r_i^2 + (depth_tap - depth_centre)^2), so a tap on another surface (the nose seen over
// the cheek, the background at depth 0) is metres or centimetres away and its R_d vanishes:
// the physics stops the bleeding that the other kernels stop with a follow-surface test.
// M(p) = sum_i R_d(|x_i - p|) A_i E(x_i) / sum_i R_d(|x_i - p|) A_i, A_i the disc area tap i
// stands for: a quadrature of the profile convolution normalised per channel, so the albedo
// texture, not the dipole's total R_d, sets the colour (as with every technique's profile).
#pragma once

#include <array>

#include "pipeline/shaders/screen_diffusion.h"

namespace skinsim::pipeline::shaders {

// The dipole's parameters as the shader reads them (bake/dipole.h, DipoleTerms), per channel.
struct DipoleProfileUniforms {
  glm::vec3 z_real{1.0f};     // mm
  glm::vec3 z_virtual{1.0f};  // mm
  glm::vec3 sigma_tr{1.0f};   // 1/mm
  glm::vec3 scale{1.0f};      // alpha' / (4 pi)
};

// R_d at squared distance r2 (mm^2), Jensen eq. 4: per pole z, d = sqrt(r^2 + z^2) and
// z (1 + sigma_tr d) e^(-sigma_tr d) / d^3; one rsqrt gives both 1/d and d.
template <class L, class Scalar>
typename L::vec3 dipole_reflectance(const Scalar& r2, const DipoleProfileUniforms& p) {
  using vec3 = typename L::vec3;
  const auto pole = [&](const glm::vec3& z) {
    const vec3 d2 = vec3(r2) + vec3(z * z);
    const vec3 inv_d = sl::rsqrt(d2);
    const vec3 d = d2 * inv_d;
    const vec3 attenuation = sl::exp2(d * vec3(-p.sigma_tr * sl::kLog2e));
    return (vec3(z) + d * vec3(z * p.sigma_tr)) * attenuation * (inv_d * inv_d * inv_d);
  };
  return (pole(p.z_real) + pole(p.z_virtual)) * vec3(p.scale);
}

struct DipoleUniforms {
  glm::vec2 focal_uv{1.0f};  // as ScreenKernelUniforms
  // Interleaved gradient noise over uv: (0.06711056 width, 0.00583715 height) (Jimenez 2014).
  glm::vec2 noise_uv{0.0f};
  DipoleProfileUniforms profile;
  int count = 0;  // taps, the centre (tap 0) included
  std::array<glm::vec2, kMaxDipoleSamples> offsets_mm{};
  std::array<float, kMaxDipoleSamples> areas_mm2{};
};

template <bool kOrthographic>
struct DipoleFSFor {
  static constexpr const char* kName = kOrthographic ? "dipole_sss_ortho_fs" : "dipole_sss_fs";
  using Uniforms = DipoleUniforms;
  SKINSIM_SL_FRAGMENT {
    SKINSIM_SL_TYPES(L);
    const auto [screen, centre, depth, uv_per_mm] =
        kernel_centre<kOrthographic, L>(in, tex, u.focal_uv);
    // The article's random directions: the disc turned per pixel by interleaved gradient
    // noise, so that a tap's share shows as fine noise rather than a shifted copy of what it
    // lands on (the eye socket, a shadow edge); deterministic, as the noise is of the pixel.
    const auto angle = interleaved_gradient_angle<L>(screen.value, u.noise_uv);
    const auto c = sl::cos(angle), s = sl::sin(angle);
    const vec2 along_x = vec2(c, s) * uv_per_mm;  // the offset's x and y axes, turned, in uv
    const vec2 along_y = vec2(-s, c) * uv_per_mm;
    // The centre (r = 0) is on the surface by definition: its weight is a constant.
    const glm::vec3 centre_weight = dipole_reflectance<sim::Exec>(0.0f, u.profile) * u.areas_mm2[0];
    vec3 sum = sl::xyz(centre) * vec3(centre_weight);
    vec3 weight_sum(centre_weight);
    for (int i = 1; i < u.count; ++i) {
      const glm::vec2 offset = u.offsets_mm[i];
      const vec4 t = tex.sample(0, screen.value + along_x * offset.x + along_y * offset.y);
      const auto dz = sl::w(t) - depth;
      const vec3 weight =
          dipole_reflectance<L>(dz * dz + glm::dot(offset, offset), u.profile) * u.areas_mm2[i];
      sum = sum + sl::xyz(t) * weight;
      weight_sum = weight_sum + weight;
    }
    return vec4(sum * sl::rcp(weight_sum), depth);
  }
};

using DipoleFS = DipoleFSFor<false>;
using DipoleOrthoFS = DipoleFSFor<true>;

}  // namespace skinsim::pipeline::shaders

// The dipole diffusion approximation of Jensen, Marschner, Levoy & Hanrahan, "A Practical
// Model for Subsurface Light Transport" (SIGGRAPH 2001): the diffuse reflectance R_d(r) of a
// semi-infinite medium lit at one point, from its absorption sigma_a, reduced scattering
// sigma_s' and relative index of refraction eta, all per colour channel, lengths in mm.
//
// The phase function enters only through sigma_s' = sigma_s (1 - g), g the mean cosine of
// the Henyey-Greenstein phase function: the diffusion approximation replaces anisotropic
// scattering by isotropic scattering at the reduced coefficient (similarity relation), and
// Jensen's measurements give sigma_s' directly.
#pragma once

#include <glm/vec3.hpp>

namespace skinsim::bake {

struct DipoleMedium {
  glm::vec3 sigma_a;        // absorption, 1/mm
  glm::vec3 sigma_s_prime;  // reduced scattering, 1/mm
  float eta = 1.3f;         // relative index of refraction
};

// Jensen et al. 2001, Figure 5 (measured with their image-based set-up, eta = 1.3):
// Skin1 sigma_s' = (0.74, 0.88, 1.01), sigma_a = (0.032, 0.17, 0.48) /mm, published diffuse
// reflectance Rd = (0.44, 0.22, 0.13); Skin2 sigma_s' = (1.09, 1.59, 1.79),
// sigma_a = (0.013, 0.070, 0.145) /mm, Rd = (0.63, 0.44, 0.34).
DipoleMedium jensen_skin1();
DipoleMedium jensen_skin2();

// Diffuse Fresnel reflectance F_dr (Egan & Hilgeman's fit, as Jensen eq. 5):
// F_dr = -1.440 / eta^2 + 0.710 / eta + 0.668 + 0.0636 eta.
float diffuse_fresnel_reflectance(float eta);

// The quantities R_d(r) is written in (Jensen section 2.4), per channel.
struct DipoleTerms {
  glm::vec3 sigma_tr;       // effective transport coefficient sqrt(3 sigma_a sigma_t'), 1/mm
  glm::vec3 alpha_prime;    // reduced albedo sigma_s' / sigma_t'
  glm::vec3 z_real;         // depth of the real source, 1 / sigma_t', mm
  glm::vec3 z_virtual;      // height of the virtual source, z_r + 4 A D = z_r (1 + 4 A / 3), mm
  float boundary_a = 1.0f;  // A = (1 + F_dr) / (1 - F_dr)
};
DipoleTerms dipole_terms(const DipoleMedium& m);

// Diffuse reflectance at distance r (mm) from the point of incidence, 1/mm^2 (Jensen eq. 4):
// R_d(r) = alpha' / (4 pi) [z_r (1 + sigma_tr d_r) e^(-sigma_tr d_r) / d_r^3
//                           + z_v (1 + sigma_tr d_v) e^(-sigma_tr d_v) / d_v^3],
// d_r = sqrt(r^2 + z_r^2), d_v = sqrt(r^2 + z_v^2).
glm::vec3 dipole_rd(const DipoleTerms& t, float r_mm);

// Total diffuse reflectance, R_d(r) integrated over the plane. Integrating eq. 4 in closed form
// (r dr = d dd, and (1 + s d) e^(-s d) / d^2 is the derivative of -e^(-s d) / d) gives
// R_d = (alpha' / 2) (e^(-sigma_tr z_r) + e^(-sigma_tr z_v))
//     = (alpha' / 2) (1 + e^(-4/3 A sqrt(3 (1 - alpha')))) e^(-sqrt(3 (1 - alpha'))).
glm::vec3 dipole_total_rd(const DipoleTerms& t);

// Fraction of the total reflectance that leaves within radius r (the same integral from 0 to r):
// 1 - [z_r e^(-sigma_tr d_r) / d_r + z_v e^(-sigma_tr d_v) / d_v]
//     / [e^(-sigma_tr z_r) + e^(-sigma_tr z_v)].
glm::vec3 dipole_cdf(const DipoleTerms& t, float r_mm);

// The radius (mm) within which the mean of the three channels' CDFs reaches u in [0, 1): the
// radii that cut the disc into rings of equal shares of the profile, for the kernels that
// integrate it (techniques/kernels.h, reference/dipole_diffusion.h).
float dipole_mean_radius(const DipoleTerms& t, float u);

// The mean over the channels of R_d(r) / R_d(total), 1/mm^2: the density whose CDF
// dipole_mean_radius inverts.
float dipole_mean_density(const DipoleTerms& t, float r_mm);

// The radius within the ring between the mean-CDF shares u0 < u1 at which the mean density
// equals its average over the ring, (u1 - u0) / ring area: one sample there, weighted by the
// ring's area, integrates the mean profile over the ring exactly (a midpoint would
// overweight the wide outer rings, over which the profile falls steeply).
float dipole_ring_radius(const DipoleTerms& t, float u0, float u1);

}  // namespace skinsim::bake

// Deterministic quadrature over the unit hemisphere around +z.
#pragma once

#include <cmath>
#include <glm/vec3.hpp>
#include <numbers>

namespace skinsim::bake {

// int over the hemisphere z >= 0 of f(w) dw, by the midpoint rule on a grid in (t, phi) with
// polar angle theta = (pi/2) t^2. The warp packs samples toward the pole, where specular lobes
// are narrow, yet keeps a bounded Jacobian (dw = sin(theta) pi t dt dphi), so any smooth
// integrand converges at the midpoint rule's O(h^2).
//
// With `mirror_y` the integrand must satisfy f(x, y, z) = f(x, -y, z) (e.g. the view vector
// lies in the xz plane): only phi in [0, pi] is sampled and the sum is doubled.
// f may return double or a glm vector of doubles (several integrals in one sweep).
template <typename F>
auto integrate_hemisphere(const F& f, int theta_samples, int phi_samples, bool mirror_y) {
  using Value = decltype(f(glm::dvec3()));
  const double phi_range = mirror_y ? std::numbers::pi : 2.0 * std::numbers::pi;
  const double dt = 1.0 / theta_samples;
  const double dphi = phi_range / phi_samples;
  Value sum{};
  for (int i = 0; i < theta_samples; ++i) {
    const double t = (i + 0.5) * dt;
    const double theta = 0.5 * std::numbers::pi * t * t;
    const double sin_theta = std::sin(theta);
    const double cos_theta = std::cos(theta);
    const double jacobian = sin_theta * std::numbers::pi * t;  // d theta / dt = pi t
    Value ring{};
    for (int j = 0; j < phi_samples; ++j) {
      const double phi = (j + 0.5) * dphi;
      const glm::dvec3 w(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
      ring += f(w);
    }
    sum += ring * jacobian;
  }
  return sum * dt * dphi * (mirror_y ? 2.0 : 1.0);
}

}  // namespace skinsim::bake

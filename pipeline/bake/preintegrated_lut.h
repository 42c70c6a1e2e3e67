// Penner's pre-integrated skin diffuse LUT (Penner & Borshukov, "Pre-Integrated Skin
// Shading", GPU Pro 2, 2011; docs/skin-techniques.md section 3, docs/luts.md):
//   D(theta, r) = int_{-pi}^{pi} saturate(cos(theta + x)) R(2 r sin(x/2)) dx
//                 / int_{-pi}^{pi} R(2 r sin(x/2)) dx
// with R the six-Gaussian skin profile: the diffuse light of a ring of radius r (a surface of
// curvature 1/r) lit at angle theta, scattered around the ring.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace skinsim::bake {

struct PreintegratedLutParams {
  int width = 256;   // N.L axis: texel i has N.L = 2 (i + 0.5) / width - 1
  int height = 256;  // curvature axis: row j has curvature (j + 0.5) / height * max_curvature
  // Curvature 1/r of the last row, in 1/mm: 1.0 covers radii down to 1 mm (eyelid and ear
  // rims; nose wings are ~2-5 mm); row 0 is nearly flat skin.
  float max_curvature_per_mm = 1.0f;
  int samples = 256;  // quadrature points per Gaussian term

  void validate() const;  // throws BakeError naming the field
};

struct PreintegratedLut {
  PreintegratedLutParams params;
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> rgb;  // linear RGB, row-major
  const glm::vec3& at(int x, int y) const { return rgb[static_cast<std::size_t>(y) * width + x]; }
};

// D(theta, r) per colour channel for N.L = cos(theta) in [-1, 1] and ring radius r > 0 (mm).
glm::vec3 preintegrated_diffuse(float n_dot_l, float radius_mm, int samples = 256);

// Multithreaded (TBB), bitwise deterministic for any thread count.
PreintegratedLut bake_preintegrated_lut(const PreintegratedLutParams& params);

}  // namespace skinsim::bake

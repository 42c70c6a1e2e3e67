// The mobile skin pipeline's 4-channel BRDF LUT (GPU Pro 5, "Realistic Real-Time Skin
// Rendering on Mobile"; docs/skin-techniques.md section 1, docs/luts.md), indexed by
// u = N.H (x) and v = N.V (y), with roughness growing along the mip chain:
//   R, G: the two Kelemen/Szirmay-Kalos lobes (encoded, see brdf_lut_encoding.h);
//   B:    the lobe-averaged Schlick Fresnel for this N.V;
//   A:    1 - the specular directional albedo for this N.V (diffuse energy conservation).
// Baking is multithreaded (TBB) and bitwise deterministic for any thread count: every row is
// computed on its own by the same sequence of operations.
#pragma once

#include <filesystem>
#include <glm/vec4.hpp>
#include <vector>

#include "pipeline/bake/brdf_lut_encoding.h"

namespace skinsim::bake {

struct BrdfLutParams {
  int width = 32;    // N.H texels at level 0 (GPU Pro 5's default LUT is 32 x 128)
  int height = 128;  // N.V texels at level 0
  // Beckmann roughness and weight of the two lobes: m = 0.3 is d'Eon & Luebke's skin value; the
  // broader, weaker second lobe follows common engine dual-lobe skin shaders.
  float m1 = 0.3f;
  float m2 = 0.6f;
  float weight1 = 0.85f;
  float weight2 = 0.15f;
  float rho_s = 0.18f;  // specular intensity (d'Eon & Luebke)
  float f0 = 0.028f;    // Schlick F0 of skin (IOR ~1.4)
  // Quadrature resolution: azimuth samples per texel for R and G, and the (theta, phi) grid
  // of the hemisphere integrals of B and A.
  int azimuth_samples = 64;
  int albedo_theta_samples = 96;
  int albedo_phi_samples = 48;

  // Throws BakeError naming the field when a value is out of range.
  void validate() const;

  bool operator==(const BrdfLutParams&) const = default;
};

struct LutLevel {
  int width = 0;
  int height = 0;
  float m1 = 0.0f;  // lobe roughness stored at this level
  float m2 = 0.0f;
  std::vector<glm::vec4> texels;  // row-major, row j has N.V = (j + 0.5) / height
  const glm::vec4& at(int x, int y) const {
    return texels[static_cast<std::size_t>(y) * width + x];
  }
};

struct BrdfLut {
  BrdfLutParams params;
  std::vector<LutLevel> levels;  // level 0 first, each half the size (at least 1) down to 1x1
};

BrdfLut bake_brdf_lut(const BrdfLutParams& params);

// Unencoded lobe response stored in R/G: pi * D(N.H, m) * <F(V.H) / (4 (V.H)^2)>, the average
// over the azimuths of H about N that give V.H > 0 and N.L > 0 (0 if none does). At N.H = 1
// it is exactly ks_lobe(1, N.V, m, f0).
float lut_lobe_response(float n_dot_h, float n_dot_v, float m, float f0, int azimuth_samples);

// Hemisphere integrals of the dual-lobe KS specular for view cosine N.V at the given lobe
// roughnesses: albedo = rho_s * sum_i w_i int ks_lobe_i N.L dw_L (the A channel is
// 1 - albedo) and the lobe-averaged Fresnel (the B channel).
struct DirectionalReflectance {
  double albedo;
  double fresnel;
};
DirectionalReflectance directional_reflectance(float n_dot_v, float m1, float m2,
                                               const BrdfLutParams& params);

enum class LutFormat { kRGBA8, kRGBA16F };

// Every texel value as the format stores it: RGBA8 clamps to [0,1] and rounds to the nearest
// 1/255; RGBA16F rounds to the nearest IEEE half (ties to even).
BrdfLut quantize(const BrdfLut& lut, LutFormat format);

// Writes one level as an 8-bit RGBA PNG (alpha = the A channel; row 0, N.V ~ 0, at the top).
void write_lut_png(const BrdfLut& lut, const std::filesystem::path& path, int level = 0);

}  // namespace skinsim::bake

#include "pipeline/bake/brdf_lut.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/vec2.hpp>
#include <numbers>
#include <string>
#include <utility>

#include "pipeline/bake/error.h"
#include "pipeline/bake/hemisphere.h"
#include "pipeline/bake/specular.h"
#include "shading/fp16.h"
#include "util/unorm8.h"

namespace skinsim::bake {
namespace {

constexpr int kMaxLutSize = 8192;
constexpr int kMaxSamples = 4096;

int level_count(int width, int height) {
  return static_cast<int>(std::bit_width(static_cast<unsigned>(std::max(width, height))));
}

}  // namespace

void BrdfLutParams::validate() const {
  const auto require = [](bool ok, const char* field, const char* rule, double value) {
    require_param(ok, "BrdfLutParams", field, rule, value);
  };
  require(width >= 1 && width <= kMaxLutSize, "width", "in [1, 8192]", width);
  require(height >= 1 && height <= kMaxLutSize, "height", "in [1, 8192]", height);
  require(std::isfinite(m1) && m1 > 0.0f, "m1", "a positive roughness", m1);
  require(std::isfinite(m2) && m2 > 0.0f, "m2", "a positive roughness", m2);
  require(std::isfinite(weight1) && weight1 >= 0.0f, "weight1", ">= 0", weight1);
  require(std::isfinite(weight2) && weight2 >= 0.0f, "weight2", ">= 0", weight2);
  require(weight1 + weight2 > 0.0f, "weight1 + weight2", "> 0", weight1 + weight2);
  require(std::isfinite(rho_s) && rho_s >= 0.0f, "rho_s", ">= 0", rho_s);
  require(f0 >= 0.0f && f0 <= 1.0f, "f0", "in [0, 1]", f0);
  require(azimuth_samples >= 1 && azimuth_samples <= kMaxSamples, "azimuth_samples", "in [1, 4096]",
          azimuth_samples);
  require(albedo_theta_samples >= 1 && albedo_theta_samples <= kMaxSamples, "albedo_theta_samples",
          "in [1, 4096]", albedo_theta_samples);
  require(albedo_phi_samples >= 1 && albedo_phi_samples <= kMaxSamples, "albedo_phi_samples",
          "in [1, 4096]", albedo_phi_samples);
}

float lut_lobe_response(float n_dot_h, float n_dot_v, float m, float f0, int azimuth_samples) {
  if (n_dot_h <= 0.0f || n_dot_v <= 0.0f) return 0.0f;
  const double u = n_dot_h;
  const double v = n_dot_v;
  const double sin_h = std::sqrt(std::max(0.0, 1.0 - u * u));
  const double sin_v = std::sqrt(std::max(0.0, 1.0 - v * v));
  // V.H = u v + sin_h sin_v cos(phi) is even in phi: sample phi in [0, pi].
  double sum = 0.0;
  int valid = 0;
  for (int j = 0; j < azimuth_samples; ++j) {
    const double phi = (j + 0.5) * std::numbers::pi / azimuth_samples;
    const double v_dot_h = u * v + sin_h * sin_v * std::cos(phi);
    const double n_dot_l = 2.0 * v_dot_h * u - v;  // L = 2 (V.H) H - V
    if (v_dot_h <= 0.0 || n_dot_l <= 0.0) continue;
    sum += fresnel_schlick(f0, static_cast<float>(v_dot_h)) / (4.0 * v_dot_h * v_dot_h);
    ++valid;
  }
  if (valid == 0) return 0.0f;
  return static_cast<float>(std::numbers::pi * beckmann_d(n_dot_h, m) * sum / valid);
}

DirectionalReflectance directional_reflectance(float n_dot_v, float m1, float m2,
                                               const BrdfLutParams& params) {
  const double v = n_dot_v;
  const glm::dvec3 view(std::sqrt(std::max(0.0, 1.0 - v * v)), 0.0, v);
  // Integrate over half vectors H: dw_L = 4 (V.H) dw_H, so ks_lobe * N.L dw_L becomes
  // pi D F N.L / (V.H) dw_H. x = with Fresnel, y = with F = 1.
  const auto integrand = [&](const glm::dvec3& h) {
    const double v_dot_h = glm::dot(view, h);
    const double n_dot_l = 2.0 * v_dot_h * h.z - v;
    if (v_dot_h <= 0.0 || n_dot_l <= 0.0) return glm::dvec2(0.0);
    const float n_dot_h = static_cast<float>(h.z);
    const double d =
        params.weight1 * beckmann_d(n_dot_h, m1) + params.weight2 * beckmann_d(n_dot_h, m2);
    const double lobe = std::numbers::pi * d * n_dot_l / v_dot_h;
    return glm::dvec2(lobe * fresnel_schlick(params.f0, static_cast<float>(v_dot_h)), lobe);
  };
  const glm::dvec2 total = integrate_hemisphere(integrand, params.albedo_theta_samples,
                                                params.albedo_phi_samples, /*mirror_y=*/true);
  return {params.rho_s * total.x, total.y > 0.0 ? total.x / total.y : params.f0};
}

BrdfLut bake_brdf_lut(const BrdfLutParams& params) {
  params.validate();
  BrdfLut lut{params, {}};
  std::vector<std::pair<int, int>> rows;  // (level, row): the units of parallel work
  for (int k = 0; k < level_count(params.width, params.height); ++k) {
    LutLevel level;
    level.width = std::max(1, params.width >> k);
    level.height = std::max(1, params.height >> k);
    level.m1 = params.m1 * roughness_scale_for_level(k);
    level.m2 = params.m2 * roughness_scale_for_level(k);
    level.texels.resize(static_cast<std::size_t>(level.width) * level.height);
    for (int j = 0; j < level.height; ++j) rows.emplace_back(k, j);
    lut.levels.push_back(std::move(level));
  }
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, rows.size()),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t r = range.begin(); r < range.end(); ++r) {
          LutLevel& level = lut.levels[rows[r].first];
          const int j = rows[r].second;
          const float v = (j + 0.5f) / level.height;
          const DirectionalReflectance refl =
              directional_reflectance(v, level.m1, level.m2, params);
          const float fresnel = static_cast<float>(refl.fresnel);
          // The KS model is not exactly energy conserving at grazing angles; A stays in [0, 1].
          const float energy = static_cast<float>(std::clamp(1.0 - refl.albedo, 0.0, 1.0));
          for (int i = 0; i < level.width; ++i) {
            const float u = (i + 0.5f) / level.width;
            const float lobe1 =
                lut_lobe_response(u, v, level.m1, params.f0, params.azimuth_samples);
            const float lobe2 =
                lut_lobe_response(u, v, level.m2, params.f0, params.azimuth_samples);
            level.texels[static_cast<std::size_t>(j) * level.width + i] = glm::vec4(
                encode_specular_lobe(lobe1), encode_specular_lobe(lobe2), fresnel, energy);
          }
        }
      });
  return lut;
}

BrdfLut quantize(const BrdfLut& lut, LutFormat format) {
  const auto store = [format](float value) {
    if (format == LutFormat::kRGBA8) {
      return kUnorm8Value[unorm8_nearest(value)];
    }
    return sim::round_to_fp16(value);  // the emulated RGBA16F texel's rounding
  };
  BrdfLut out = lut;
  for (LutLevel& level : out.levels) {
    for (glm::vec4& texel : level.texels) {
      for (int c = 0; c < 4; ++c) texel[c] = store(texel[c]);
    }
  }
  return out;
}

}  // namespace skinsim::bake

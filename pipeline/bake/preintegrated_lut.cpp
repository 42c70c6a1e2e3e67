#include "pipeline/bake/preintegrated_lut.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "pipeline/bake/error.h"
#include "pipeline/bake/skin_profile.h"

namespace skinsim::bake {
namespace {

// Midpoint quadrature nodes of one Gaussian term of the profile around the ring: angles x and
// weights G(v, 2 r sin(x/2)) dx, over the range where the chord is within 6 standard
// deviations (beyond that the Gaussian is below e^-18 of its peak).
struct RingQuadrature {
  std::vector<double> cos_x;
  std::vector<double> sin_x;
  std::vector<double> weight;
  double total = 0.0;  // int G dx, the term's share of the denominator
};

RingQuadrature ring_quadrature(double variance, double radius, int samples) {
  const double sigma = std::sqrt(variance);
  const double extent = 2.0 * std::asin(std::min(1.0, 3.0 * sigma / radius));
  const double dx = 2.0 * extent / samples;
  RingQuadrature q;
  for (int k = 0; k < samples; ++k) {
    const double x = -extent + (k + 0.5) * dx;
    const double chord = 2.0 * radius * std::sin(0.5 * x);
    const double g =
        std::exp(-chord * chord / (2.0 * variance)) / (2.0 * std::numbers::pi * variance);
    q.cos_x.push_back(std::cos(x));
    q.sin_x.push_back(std::sin(x));
    q.weight.push_back(g * dx);
    q.total += g * dx;
  }
  return q;
}

std::array<RingQuadrature, 6> ring_quadratures(double radius, int samples) {
  std::array<RingQuadrature, 6> out;
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = ring_quadrature(skin_gaussians()[i].variance_mm2, radius, samples);
  }
  return out;
}

glm::vec3 diffuse(const std::array<RingQuadrature, 6>& rings, double n_dot_l) {
  const double cos_t = std::clamp(n_dot_l, -1.0, 1.0);
  const double sin_t = std::sqrt(1.0 - cos_t * cos_t);
  glm::dvec3 numerator(0.0);
  glm::dvec3 denominator(0.0);
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const RingQuadrature& q = rings[i];
    double lit = 0.0;
    for (std::size_t k = 0; k < q.weight.size(); ++k) {
      const double cos_sum = cos_t * q.cos_x[k] - sin_t * q.sin_x[k];  // cos(theta + x)
      lit += std::max(0.0, cos_sum) * q.weight[k];
    }
    const glm::dvec3 w(skin_gaussians()[i].weight);
    numerator += w * lit;
    denominator += w * q.total;
  }
  return glm::vec3(numerator / denominator);
}

}  // namespace

void PreintegratedLutParams::validate() const {
  const auto require = [](bool ok, const char* field, const char* rule, double value) {
    require_param(ok, "PreintegratedLutParams", field, rule, value);
  };
  require(width >= 1 && width <= 8192, "width", "in [1, 8192]", width);
  require(height >= 1 && height <= 8192, "height", "in [1, 8192]", height);
  require(std::isfinite(max_curvature_per_mm) && max_curvature_per_mm > 0.0f,
          "max_curvature_per_mm", "a positive curvature (1/mm)", max_curvature_per_mm);
  require(samples >= 2 && samples <= 65536, "samples", "in [2, 65536]", samples);
}

glm::vec3 preintegrated_diffuse(float n_dot_l, float radius_mm, int samples) {
  if (!(radius_mm > 0.0f) || samples < 2) {
    throw BakeError("preintegrated_diffuse: radius_mm must be > 0 and samples >= 2, got " +
                    std::to_string(radius_mm) + " and " + std::to_string(samples));
  }
  return diffuse(ring_quadratures(radius_mm, samples), n_dot_l);
}

PreintegratedLut bake_preintegrated_lut(const PreintegratedLutParams& params) {
  params.validate();
  PreintegratedLut lut{
      params, params.width, params.height,
      std::vector<glm::vec3>(static_cast<std::size_t>(params.width) * params.height)};
  tbb::parallel_for(
      tbb::blocked_range<int>(0, params.height), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j < rows.end(); ++j) {
          const double curvature = (j + 0.5) / params.height * params.max_curvature_per_mm;
          const auto rings = ring_quadratures(1.0 / curvature, params.samples);
          for (int i = 0; i < params.width; ++i) {
            const double n_dot_l = 2.0 * (i + 0.5) / params.width - 1.0;
            lut.rgb[static_cast<std::size_t>(j) * params.width + i] = diffuse(rings, n_dot_l);
          }
        }
      });
  return lut;
}

}  // namespace skinsim::bake

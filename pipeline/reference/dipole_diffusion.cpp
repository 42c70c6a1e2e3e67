#include "pipeline/reference/dipole_diffusion.h"

#include <cmath>
#include <numbers>

namespace skinsim::pipeline {

namespace {
constexpr float kCoverage = 0.999f;  // of the channels' mean profile
constexpr int kTableSize = 65536;    // steps of ~0.04 mm^2 for Skin1: z_r^2 is 0.45 mm^2 in blue
// The table reaches twice the grid's radius: farther surface points (another surface behind
// or in front) weigh under 1e-7 of the centre for every channel.
constexpr float kTableReach = 2.0f;
}  // namespace

DipoleDiffusion::DipoleDiffusion(const sim::RenderTarget& position, float kind_skin,
                                 const std::vector<glm::vec3>& irradiance, const View& view,
                                 float units_per_mm, const bake::DipoleTerms& terms)
    : position_(position),
      kind_skin_(kind_skin),
      irradiance_(irradiance),
      view_(view),
      units_per_mm_(units_per_mm) {
  const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
  const auto share = [](int ring) { return kCoverage * static_cast<float>(ring) / kRings; };
  const auto radius = [&](int ring) { return bake::dipole_mean_radius(terms, share(ring)); };
  // The centre stands for the innermost disc (p itself, always skin); then the rings, each
  // sampled at the radius where the profile equals its ring average (as the dipole kernel).
  samples_.push_back({glm::vec2(0.0f), share(1) / bake::dipole_mean_density(terms, 0.0f)});
  for (int ring = 1; ring < kRings; ++ring) {
    const float inner = radius(ring), outer = radius(ring + 1);
    const float middle = bake::dipole_ring_radius(terms, share(ring), share(ring + 1));
    const float area = std::numbers::pi_v<float> * (outer * outer - inner * inner) / kAngles;
    for (int a = 0; a < kAngles; ++a) {
      const float angle = golden * ring + 2.0f * std::numbers::pi_v<float> * a / kAngles;
      samples_.push_back({middle * glm::vec2(std::cos(angle), std::sin(angle)), area});
    }
  }
  const float reach = kTableReach * radius(kRings);
  table_step_ = reach * reach / kTableSize;
  table_.resize(kTableSize + 2);
  for (int i = 0; i < kTableSize + 2; ++i) {
    table_[i] = bake::dipole_rd(terms, std::sqrt(table_step_ * static_cast<float>(i)));
  }
}

glm::vec3 DipoleDiffusion::profile(float distance2_mm2) const {
  const float f = distance2_mm2 / table_step_;
  if (f >= static_cast<float>(kTableSize)) return glm::vec3(0.0f);
  const int i = static_cast<int>(f);
  return table_[i] + (table_[i + 1] - table_[i]) * (f - static_cast<float>(i));
}

void DipoleDiffusion::row(int y, int x_begin, int x_end, glm::vec3* out) const {
  for (int x = x_begin; x < x_end; ++x) {
    if (position_.at(x, y).w == kind_skin_) out[x - x_begin] = at(x, y);
  }
}

glm::vec3 DipoleDiffusion::at(int x, int y) const {
  const int w = position_.width, h = position_.height;
  const glm::vec3 p(position_.at(x, y));
  const float px_per_mm = view_.pixels_per_unit(glm::length(p - view_.eye)) * units_per_mm_;
  const float mm_per_unit = 1.0f / units_per_mm_;
  glm::vec3 sum(0.0f), weight_sum(0.0f);
  for (const Sample& s : samples_) {
    const int qx = x + static_cast<int>(std::lround(s.offset_mm.x * px_per_mm));
    const int qy = y - static_cast<int>(std::lround(s.offset_mm.y * px_per_mm));
    if (qx < 0 || qx >= w || qy < 0 || qy >= h) continue;
    const glm::vec4 q = position_.at(qx, qy);
    if (q.w != kind_skin_) continue;
    const glm::vec3 d = (glm::vec3(q) - p) * mm_per_unit;
    const glm::vec3 weight = profile(glm::dot(d, d)) * s.area_mm2;
    sum += weight * irradiance_[static_cast<size_t>(qy) * w + qx];
    weight_sum += weight;
  }
  return sum / weight_sum;  // the centre's weight is R_d(0) > 0
}

}  // namespace skinsim::pipeline

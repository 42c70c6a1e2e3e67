#include "scene/head_measure.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace skinsim::scene {
namespace {

constexpr int kSlices = 400;
constexpr float kNoseSearchShare = 2.0f / 3.0f;  // of the skin's height, from the top
// In crown-to-nose lengths: where the chin is looked for, and how far the profile falls back
// under it.
constexpr float kChinBelowNoseMin = 0.3f, kChinBelowNoseMax = 0.9f;
constexpr float kUnderChinFallBack = 0.1f;

// One horizontal cut of the surface.
struct Slice {
  bool any = false;
  glm::vec3 front{0.0f, 0.0f, std::numeric_limits<float>::lowest()};  // max z point
  float min_x = std::numeric_limits<float>::max(), max_x = std::numeric_limits<float>::lowest();
  float min_z = std::numeric_limits<float>::max();
  void add(const glm::vec3& p) {
    if (!any || p.z > front.z) front = p;
    any = true;
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
    min_z = std::min(min_z, p.z);
  }
};

bool is_skin(const Scene& scene, const Mesh& mesh) {
  return scene.materials[static_cast<std::size_t>(mesh.material)].kind == MaterialKind::kSkin;
}

}  // namespace

HeadMeasure measure_head(const Scene& scene) {
  HeadMeasure out;
  // Crown: the first highest vertex (deterministic: meshes and indices in order).
  glm::vec3 crown(0.0f, std::numeric_limits<float>::lowest(), 0.0f);
  float bottom = std::numeric_limits<float>::max();
  for (const Mesh& m : scene.meshes) {
    if (!is_skin(scene, m)) continue;
    for (std::uint32_t i : m.indices) {
      const glm::vec3& p = m.positions[i];
      if (p.y > crown.y) crown = p;
      bottom = std::min(bottom, p.y);
    }
  }
  const float step = (crown.y - bottom) / kSlices;
  if (!(step > 0.0f)) {
    out.why_not = bottom > crown.y ? "no material is skin" : "the skin has no height";
    return out;
  }
  const auto plane_y = [&](int i) { return crown.y - (static_cast<float>(i) + 0.5f) * step; };
  std::vector<Slice> slices(kSlices);
  for (const Mesh& m : scene.meshes) {
    if (!is_skin(scene, m)) continue;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      const glm::vec3 v[3] = {m.positions[m.indices[t]], m.positions[m.indices[t + 1]],
                              m.positions[m.indices[t + 2]]};
      const float lo = std::min({v[0].y, v[1].y, v[2].y}), hi = std::max({v[0].y, v[1].y, v[2].y});
      const int first = std::max(0, static_cast<int>(std::ceil((crown.y - hi) / step - 0.5f)));
      const int last =
          std::min(kSlices - 1, static_cast<int>(std::floor((crown.y - lo) / step - 0.5f)));
      for (int i = first; i <= last; ++i) {
        const float y = plane_y(i);
        for (int e = 0; e < 3; ++e) {
          const glm::vec3& p = v[e];
          const glm::vec3& q = v[(e + 1) % 3];
          if ((p.y - y) * (q.y - y) > 0.0f) continue;
          const float t_at = p.y == q.y ? 0.0f : (y - p.y) / (q.y - p.y);
          slices[static_cast<std::size_t>(i)].add(glm::mix(p, q, t_at));
        }
      }
    }
  }

  int nose = -1;
  for (int i = 0; i < static_cast<int>(kSlices * kNoseSearchShare); ++i) {
    const Slice& s = slices[static_cast<std::size_t>(i)];
    if (s.any && (nose < 0 || s.front.z > slices[static_cast<std::size_t>(nose)].front.z)) nose = i;
  }
  if (nose <= 0) {
    out.why_not = "no face found in the upper two thirds of the skin (no point sticks forward)";
    return out;
  }
  const glm::vec3 nose_tip = slices[static_cast<std::size_t>(nose)].front;
  const float crown_to_nose = crown.y - nose_tip.y;

  int chin = -1;
  bool under_chin = false;
  for (int i = nose; i < kSlices && !under_chin; ++i) {
    const Slice& s = slices[static_cast<std::size_t>(i)];
    const float below = (nose_tip.y - plane_y(i)) / crown_to_nose;
    if (!s.any || below < kChinBelowNoseMin) continue;
    if (below > kChinBelowNoseMax) break;
    const Slice* best = chin < 0 ? nullptr : &slices[static_cast<std::size_t>(chin)];
    under_chin = best && s.front.z < best->front.z - kUnderChinFallBack * crown_to_nose;
    // 45 degrees between forward (+Z) and down.
    if (!best || s.front.z - s.front.y > best->front.z - best->front.y) chin = i;
  }
  if (!under_chin) {
    out.why_not = fmt::format(
        "the front profile does not fall back under a chin {}-{} crown-to-nose lengths below "
        "the most forward point (is +Y up and the face towards +Z?)",
        kChinBelowNoseMin, kChinBelowNoseMax);
    return out;
  }
  const glm::vec3 chin_point = slices[static_cast<std::size_t>(chin)].front;

  HeadLandmarks head;
  head.crown = crown;
  head.nose_tip = nose_tip;
  head.chin = chin_point;
  head.box_min =
      glm::vec3(std::numeric_limits<float>::max(), chin_point.y, std::numeric_limits<float>::max());
  head.box_max = glm::vec3(std::numeric_limits<float>::lowest(), crown.y,
                           std::numeric_limits<float>::lowest());
  for (int i = 0; i <= chin; ++i) {
    const Slice& s = slices[static_cast<std::size_t>(i)];
    if (!s.any) continue;
    head.box_min.x = std::min(head.box_min.x, s.min_x);
    head.box_max.x = std::max(head.box_max.x, s.max_x);
    head.box_min.z = std::min(head.box_min.z, s.min_z);
    head.box_max.z = std::max(head.box_max.z, s.front.z);
  }
  out.head = head;
  return out;
}

}  // namespace skinsim::scene

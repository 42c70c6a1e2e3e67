#include "scene/mesh_attributes.h"

#include <cmath>
#include <cstring>
#include <initializer_list>
#include <unordered_map>

namespace skinsim::scene {
namespace {

struct PositionKey {
  std::uint32_t x, y, z;
  bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) + k.y * 0xBF58476D1CE4E5B9ull;
    h ^= (h >> 31) + k.z * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

PositionKey key_of(const glm::vec3& p) {
  // +0.0f turns -0.0 into +0.0 so both weld.
  const glm::vec3 q = p + glm::vec3(0.0f);
  PositionKey k{};
  std::memcpy(&k.x, &q.x, 4);
  std::memcpy(&k.y, &q.y, 4);
  std::memcpy(&k.z, &q.z, 4);
  return k;
}

}  // namespace

glm::vec3 any_orthogonal(const glm::vec3& n) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  return glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

std::vector<glm::vec3> compute_smooth_normals(const std::vector<glm::vec3>& positions,
                                              const std::vector<std::uint32_t>& indices) {
  // Map every vertex to a representative vertex with the same position.
  std::vector<std::uint32_t> rep(positions.size());
  std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> first;
  first.reserve(positions.size());
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    rep[i] = first.try_emplace(key_of(positions[i]), i).first->second;
  }
  std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3& a = positions[indices[t]];
    const glm::vec3& b = positions[indices[t + 1]];
    const glm::vec3& c = positions[indices[t + 2]];
    const glm::vec3 face = glm::cross(b - a, c - a);
    for (int k = 0; k < 3; ++k) sum[rep[indices[t + k]]] += face;
  }
  std::vector<glm::vec3> normals(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3 s = sum[rep[i]];
    const float len = glm::length(s);
    normals[i] = len > 0.0f && std::isfinite(len) ? s / len : glm::vec3(0.0f, 0.0f, 1.0f);
  }
  return normals;
}

std::vector<glm::vec4> compute_tangents(const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs,
                                        const std::vector<std::uint32_t>& indices) {
  std::vector<glm::vec3> tan_sum(positions.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> bitan_sum(positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
    const glm::vec3 e1 = positions[i1] - positions[i0];
    const glm::vec3 e2 = positions[i2] - positions[i0];
    // v' = 1 - v: MikkTSpace's bottom-left UV origin.
    const glm::vec2 d1(uvs[i1].x - uvs[i0].x, uvs[i0].y - uvs[i1].y);
    const glm::vec2 d2(uvs[i2].x - uvs[i0].x, uvs[i0].y - uvs[i2].y);
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-20f) continue;
    // Solve e = dP/du' * du' + dP/dv' * dv'. The directions are normalised and weighted
    // by the triangle's area, so the UV scale of a triangle does not change its weight.
    const float r = 1.0f / det;
    const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) * r;
    const glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) * r;
    const float area = 0.5f * glm::length(glm::cross(e1, e2));
    const float lu = glm::length(dpdu), lv = glm::length(dpdv);
    if (!(lu > 0.0f) || !(lv > 0.0f) || !std::isfinite(lu) || !std::isfinite(lv)) continue;
    for (std::uint32_t i : {i0, i1, i2}) {
      tan_sum[i] += dpdu * (area / lu);
      bitan_sum[i] += dpdv * (area / lv);
    }
  }
  std::vector<glm::vec4> tangents(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& n = normals[i];
    glm::vec3 t = tan_sum[i] - n * glm::dot(n, tan_sum[i]);  // Gram-Schmidt
    const float len = glm::length(t);
    if (!(len > 1e-12f) || !std::isfinite(len)) {
      tangents[i] = glm::vec4(any_orthogonal(n), 1.0f);
      continue;
    }
    t /= len;
    const float w = glm::dot(glm::cross(n, t), bitan_sum[i]) < 0.0f ? -1.0f : 1.0f;
    tangents[i] = glm::vec4(t, w);
  }
  return tangents;
}

}  // namespace skinsim::scene

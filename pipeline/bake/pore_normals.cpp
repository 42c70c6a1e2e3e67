#include "pipeline/bake/pore_normals.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace skinsim::bake {

namespace {

// A 32-bit integer hash (Wang's), mapped to [0, 1).
float hash01(std::uint32_t x) {
  x = (x ^ 61u) ^ (x >> 16);
  x *= 9u;
  x ^= x >> 4;
  x *= 0x27d4eb2du;
  x ^= x >> 15;
  return static_cast<float>(x >> 8) / static_cast<float>(1u << 24);
}

// Shortest signed distance from a to b on a circle of length `period`.
float wrapped(float d, float period) {
  return d - period * std::round(d / period);
}

}  // namespace

std::vector<glm::vec3> bake_pore_normals(const PoreNormalParams& p) {
  const int n = p.size;
  const float cell = static_cast<float>(n) / static_cast<float>(p.cells);
  const float period = static_cast<float>(n);
  // Pore centres: one per cell, anywhere in its middle 60 %.
  std::vector<glm::vec2> centres;
  for (int cy = 0; cy < p.cells; ++cy) {
    for (int cx = 0; cx < p.cells; ++cx) {
      const auto id = static_cast<std::uint32_t>(cy * p.cells + cx) * 2u + p.seed * 7919u;
      centres.emplace_back((static_cast<float>(cx) + 0.2f + 0.6f * hash01(id)) * cell,
                           (static_cast<float>(cy) + 0.2f + 0.6f * hash01(id + 1u)) * cell);
    }
  }
  // Height at texel centres: minus a Gaussian dimple per nearby pore (3 sigma reach).
  std::vector<float> height(static_cast<std::size_t>(n) * n, 0.0f);
  const float inv_two_var = 1.0f / (2.0f * p.radius * p.radius);
  const float reach2 = 9.0f * p.radius * p.radius;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      float h = 0.0f;
      for (const glm::vec2& c : centres) {
        const float dx = wrapped(static_cast<float>(x) + 0.5f - c.x, period);
        const float dy = wrapped(static_cast<float>(y) + 0.5f - c.y, period);
        const float r2 = dx * dx + dy * dy;
        if (r2 < reach2) h -= p.depth * std::exp(-r2 * inv_two_var);
      }
      height[static_cast<std::size_t>(y) * n + x] = h;
    }
  }
  // Normals from central differences, wrapping at the edges.
  const auto at = [&](int x, int y) {
    return height[static_cast<std::size_t>((y + n) % n) * n +
                  static_cast<std::size_t>((x + n) % n)];
  };
  std::vector<glm::vec3> normals;
  normals.reserve(height.size());
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const float dhdx = 0.5f * (at(x + 1, y) - at(x - 1, y));
      const float dhdy = 0.5f * (at(x, y + 1) - at(x, y - 1));
      normals.push_back(glm::normalize(glm::vec3(-dhdx, -dhdy, 1.0f)));
    }
  }
  return normals;
}

}  // namespace skinsim::bake

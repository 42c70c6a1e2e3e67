#include "scene/hash_noise.h"

#include <cmath>

namespace skinsim::scene {
namespace {

float fade(float t) {
  return t * t * (3.0f - 2.0f * t);
}

float signed_hash(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed) {
  return 2.0f * hash_unit(x, y, z, seed) - 1.0f;
}

std::int32_t wrap(std::int32_t i, std::int32_t period) {
  const std::int32_t m = i % period;
  return m < 0 ? m + period : m;
}

}  // namespace

std::uint32_t hash_lattice(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed) {
  // Combine with large odd constants, then one lowbias32 finaliser round.
  std::uint32_t h = static_cast<std::uint32_t>(x) * 0x8DA6B343u ^
                    static_cast<std::uint32_t>(y) * 0xD8163841u ^
                    static_cast<std::uint32_t>(z) * 0xCB1AB31Fu ^ seed * 0x9E3779B9u;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return h;
}

float hash_unit(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed) {
  return static_cast<float>(hash_lattice(x, y, z, seed) >> 8) * (1.0f / 16777216.0f);
}

float value_noise(const glm::vec3& p, std::uint32_t seed) {
  const glm::vec3 f = glm::floor(p);
  const auto x = static_cast<std::int32_t>(f.x), y = static_cast<std::int32_t>(f.y),
             z = static_cast<std::int32_t>(f.z);
  const float tx = fade(p.x - f.x), ty = fade(p.y - f.y), tz = fade(p.z - f.z);
  float c[2][2];
  for (int dz = 0; dz < 2; ++dz) {
    for (int dy = 0; dy < 2; ++dy) {
      const float a = signed_hash(x, y + dy, z + dz, seed);
      const float b = signed_hash(x + 1, y + dy, z + dz, seed);
      c[dz][dy] = a + (b - a) * tx;
    }
  }
  const float near = c[0][0] + (c[0][1] - c[0][0]) * ty;
  const float far = c[1][0] + (c[1][1] - c[1][0]) * ty;
  return near + (far - near) * tz;
}

float value_noise_periodic(const glm::vec2& p, std::int32_t period_x, std::uint32_t seed) {
  const glm::vec2 f = glm::floor(p);
  const auto x = static_cast<std::int32_t>(f.x), y = static_cast<std::int32_t>(f.y);
  const float tx = fade(p.x - f.x), ty = fade(p.y - f.y);
  const std::int32_t x0 = wrap(x, period_x), x1 = wrap(x + 1, period_x);
  const float a = signed_hash(x0, y, 0, seed), b = signed_hash(x1, y, 0, seed);
  const float c = signed_hash(x0, y + 1, 0, seed), d = signed_hash(x1, y + 1, 0, seed);
  const float top = a + (b - a) * tx, bottom = c + (d - c) * tx;
  return top + (bottom - top) * ty;
}

float fbm(const glm::vec3& p, int octaves, std::uint32_t seed) {
  float sum = 0.0f, amp = 1.0f, norm = 0.0f;
  glm::vec3 q = p;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * value_noise(q, seed + static_cast<std::uint32_t>(i) * 101u);
    norm += amp;
    amp *= 0.5f;
    q *= 2.0f;
  }
  return sum / norm;
}

}  // namespace skinsim::scene

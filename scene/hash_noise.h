// Deterministic noise from integer hashing (no std::rand, no global state): the same
// inputs give the same values on every platform and thread count.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

namespace skinsim::scene {

// 32-bit avalanche hash of a lattice point and a seed (a "lowbias32" finaliser,
// C. Wellons, "Hash function prospector", 2018).
std::uint32_t hash_lattice(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed);

// Hash mapped to [0, 1).
float hash_unit(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t seed);

// Trilinear value noise with smoothstep fade, range [-1, 1], lattice spacing 1.
float value_noise(const glm::vec3& p, std::uint32_t seed);

// 2D value noise that repeats every `period_x` lattice cells along x (for textures that
// wrap around in u). Range [-1, 1].
float value_noise_periodic(const glm::vec2& p, std::int32_t period_x, std::uint32_t seed);

// Sum of `octaves` value-noise octaves (frequency x2, amplitude x0.5), normalised to [-1, 1].
float fbm(const glm::vec3& p, int octaves, std::uint32_t seed);

}  // namespace skinsim::scene

// The burley technique's own knobs (burley.cpp binds them), nested in PipelineConfig as
// `burley`.
#pragma once

#include <glm/vec3.hpp>
#include <optional>

namespace skinsim::pipeline {

// Size of the Burley shader's uniform tap array (each tap: a vec2 offset and an RGB weight,
// two uniform vectors; 64 taps fit the SGX's fragment uniform file).
inline constexpr int kMaxBurleySamples = 64;

struct BurleyParams {
  int samples = 16;
  // Scattering distance d per channel (mm); by default fitted to the six-Gaussian profile's
  // mean scattering radius (techniques/kernels.h).
  std::optional<glm::vec3> distance_mm;
};

}  // namespace skinsim::pipeline

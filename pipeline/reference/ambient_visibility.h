// How much of the light from all around a skin point reaches it past the character's own
// geometry: the visibility of the reference's ambient and environment terms.
//
// The reference lights skin with a uniform ambient radiance (lighting.h: `ambient`) and
// reflects the studio environment's cosine-filtered light with Fresnel (docs/reference.md).
// Both arrive from the whole hemisphere; under the nose, in the lips' crease or under the
// chin the face hides part of it, as it does in a path tracer (Cycles, the truth of
// docs/validation.md). The visible part is estimated as pbrt's ambient occlusion integrator
// estimates it (pbrt-v4's AOIntegrator with cosine sampling: cosine-weighted directions, so
// each open ray counts equally and the estimate is the open share): kRays directions around
// the vertex normal, cast with Embree against the character's meshes (skin and eyes).
//
// The directions are a Fibonacci lattice mapped onto the hemisphere by Malley's method (the
// cosine-weighted map; Pharr, Jakob and Humphreys, "Physically Based Rendering", 3rd ed.,
// 13.6.3), shifted per pixel by two values of interleaved gradient noise
// (pixel_noise.h; a Cranley-Patterson rotation of the lattice): a fixed, stratified pattern
// per pixel, so neighbouring pixels cover the hemisphere between them and the skin's diffusion
// averages their noise.
//
// What a point sees beyond the character counts as the environment: the backdrop and the
// shirt (kind "other") do not occlude, as they cast no shadows in the truth's scene either
// (driver/truth/truth_scene.h); the light they reflect onto the skin is no part of the reference.
#pragma once

#include <glm/glm.hpp>

#include "pipeline/bake/ray_scene.h"
#include "pipeline/gpu_scene.h"
#include "sim/texture.h"

namespace skinsim::pipeline::reference {

// The environment cube's top level at `direction`, bilinear within a face.
glm::vec3 sample_cube(const sim::TextureCube& cube, const glm::vec3& direction);

struct AmbientVisibility {
  // The cosine-weighted share of the hemisphere that no geometry blocks: the uniform
  // ambient's visibility.
  float ambient = 1.0f;
  // The share of the environment's cosine-weighted light (per channel) arriving along open
  // directions: each ray looks the sharp environment up in its direction, and the
  // cosine-filtered environment the reference reflects is scaled by open / all (Heitz, Hill
  // and McGuire's ratio estimator, "Combining Analytic Direct Illumination and Stochastic
  // Shadows", I3D 2018: exact where nothing is blocked, noisy only where something is).
  glm::vec3 environment{1.0f};
};

class AmbientRays {
 public:
  // Measured on the built-in head (docs/reference.md): the reference's noise against 1024
  // rays and its cost per ray count.
  static constexpr int kRays = 32;

  explicit AmbientRays(const GpuScene& gs);

  // At `origin` (off the smooth surface, as the shadow rays start) around the unit vertex
  // normal `n`, for pixel (x, y); rays start `t_near` along their direction.
  AmbientVisibility at(const glm::vec3& origin, const glm::vec3& n, int x, int y,
                       float t_near) const;

 private:
  bake::RayScene occluders_;
  const sim::TextureCube& environment_;
};

}  // namespace skinsim::pipeline::reference

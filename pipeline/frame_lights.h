// The light of one frame on the emulated GPU: the lights with the knobs applied
// (lighting.h), the key light's shadow map and its pass, and what every lit pass binds and
// sets from them (shaders/lights.h).
//
// The shadow map is a depth-only render (its own pass, "shadow": the tiler for every mesh,
// ISP-only tiles, the depth stored to DRAM because a later pass samples it) from an
// orthographic camera along the key light, fitted to the bounds of every mesh (the Changyou
// engine article's dedicated light camera fitted to the character).
#pragma once

#include <memory>
#include <vector>

#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"
#include "pipeline/lighting.h"
#include "pipeline/shaders/lights.h"
#include "sim/gpu.h"

namespace skinsim::pipeline {

// Whether a program computes transmission (it then needs the thickness varying): the light
// passes of the buffer techniques and the skin pass of the single-pass ones.
enum class Transmission { kComputedHere, kComputedElsewhere };

class FrameLights {
 public:
  // Renders the shadow pass when the config has shadows, appending its counters to `passes`.
  FrameLights(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu,
              std::vector<sim::PassCounters>& passes);
  FrameLights(const FrameLights&) = delete;
  FrameLights& operator=(const FrameLights&) = delete;

  const FrameLighting& lighting() const { return lighting_; }
  const shaders::LightUniforms& uniforms() const { return uniforms_; }
  // For the vertex shader feeding a lit fragment shader.
  shaders::LightVertexUniforms vertex_uniforms(Transmission transmission) const;
  // Binds the shadow map to a draw (when there are shadows).
  void bind(sim::DrawCall& draw) const;
  // Width of the filtered shadow penumbra on the surface, mm (the PCF footprint).
  float penumbra_mm() const { return penumbra_mm_; }
  // The shadow map as stored (depth in red), for viewing; null without shadows.
  const sim::RenderTarget* shadow_map() const { return shadows_ ? &depth_ : nullptr; }

 private:
  FrameLighting lighting_;
  shaders::LightUniforms uniforms_;
  bool shadows_ = false;
  bool transmission_ = false;
  glm::mat4 shadow_matrix_{1.0f};  // world -> (u, v, depth), tap 0's offset included
  float normal_offset_ = 0.0f;     // world units
  float penumbra_mm_ = 0.0f;
  sim::RenderTarget depth_;
  sim::Texture2D texture_;
};

}  // namespace skinsim::pipeline

// What every comparison technique's frame starts from: the view, the frame target, and the
// BRDF LUT when the specular model reads it.
#pragma once

#include <memory>

#include "pipeline/brdf_lut_texture.h"
#include "pipeline/frame.h"
#include "pipeline/shaders/technique_bindings.h"
#include "pipeline/technique.h"

namespace skinsim::pipeline {

inline FrameOutput start_frame(const GpuScene& scene, const PipelineConfig& config) {
  FrameOutput out;
  out.view = make_view(scene, config);
  out.frame = sim::RenderTarget("frame", config.width, config.height, sim::TexelFormat::kRGBA8);
  return out;
}

// The BRDF LUT, only for the ks_lut specular model (the others evaluate in ALU).
inline std::shared_ptr<const BrdfLutTexture> brdf_lut_for(const PipelineConfig& config) {
  if (!reads_brdf_lut(config)) return nullptr;
  return BrdfLutTexture::shared(config);
}

inline void bind_brdf_lut(const std::shared_ptr<const BrdfLutTexture>& lut, sim::DrawCall& draw) {
  if (lut) draw.textures.textures[shaders::TechniqueBindings::kBrdfLut] = &lut->texture();
}

}  // namespace skinsim::pipeline

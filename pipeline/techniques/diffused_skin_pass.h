// The `skin` render of the techniques that diffuse light in a buffer first (burley and
// ssss in screen space, texture-space in the UV layout): DiffusedSkinFS reading it.
#pragma once

#include "pipeline/config.h"
#include "pipeline/frame_lights.h"
#include "pipeline/gpu_scene.h"
#include "pipeline/shaders/diffused_skin.h"
#include "sim/gpu.h"

namespace skinsim::pipeline {

sim::PassCounters diffused_skin_pass(const GpuScene& scene, const View& view,
                                     const PipelineConfig& config, const FrameLights& lights,
                                     shaders::DiffusionSource source,
                                     const sim::RenderTarget& diffused, sim::RenderTarget& frame,
                                     sim::Gpu& gpu);

}  // namespace skinsim::pipeline

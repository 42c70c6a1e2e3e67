// The GPU Pro 5 mobile skin pipeline as a frame of render passes on the emulated GPU:
//   irradiance -> (blur_h, blur_v) x iterations -> skin
// where `skin` is the framebuffer render: background, eyes and skin draws in one render
// (a real app switches no render target between them, so it pays no extra resolve). At
// LOD distance the frame is the single `skin` render with the one-pass shader.
#pragma once

#include <vector>

#include "pipeline/brdf_lut_texture.h"
#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"
#include "sim/counters.h"
#include "sim/gpu.h"
#include "sim/render_target.h"

namespace skinsim::pipeline {

struct FrameOutput {
  View view;
  bool lod = false;  // the single-pass distant-skin shader ran
  std::vector<sim::PassCounters> passes;
  sim::RenderTarget frame;       // the final image (display-encoded RGBA8)
  sim::RenderTarget irradiance;  // integration buffer before the blur (empty at LOD)
  sim::RenderTarget blurred;     // after the last blur iteration (empty at LOD)
  float blur_sigma_pixels = 0.0f;  // per iteration, in buffer texels
};

// Renders one frame of `gpu_scene` with `config` (validated) on `gpu`. `lut` is the BRDF LUT
// baked for the config.
FrameOutput render_skin_frame(const GpuScene& gpu_scene, const PipelineConfig& config,
                              const BrdfLutTexture& lut, sim::Gpu& gpu);

// Render resolution for a config: its own, or the given default (the device's display).
std::pair<int, int> render_size(const PipelineConfig& config, int default_width,
                                int default_height);

}  // namespace skinsim::pipeline

// The GPU Pro 5 mobile skin pipeline as a frame of render passes on the emulated GPU:
//   irradiance -> (blur_h, blur_v) x iterations -> skin
// where `skin` is the framebuffer render: background, eyes and skin draws in one render
// (a real app switches no render target between them, so it pays no extra resolve). At
// LOD distance the frame is the single `skin` render with the one-pass shader.
#pragma once

#include "pipeline/brdf_lut_texture.h"
#include "pipeline/frame.h"
#include "pipeline/frame_lights.h"

namespace skinsim::pipeline {

enum class MobileMode {
  kAuto,      // the single-pass shader only beyond config.mobile.lod_distance_m
  kForceLod,  // always the single-pass shader (the `lod` technique)
};

FrameOutput render_mobile_frame(const GpuScene& gpu_scene, const PipelineConfig& config,
                                const FrameLights& lights, sim::Gpu& gpu, MobileMode mode);

}  // namespace skinsim::pipeline

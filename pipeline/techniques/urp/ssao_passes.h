// The urp technique's screen-space AO as passes of the emulated GPU (shaders/ssao.h):
// depth_normal -> ssao -> ssao_h -> ssao_v.
#pragma once

#include <vector>

#include "pipeline/config.h"
#include "pipeline/frame.h"
#include "pipeline/gpu_scene.h"
#include "pipeline/shaders/ssao.h"
#include "sim/gpu.h"

namespace skinsim::pipeline {

// Renders the four passes into `out` (their counters; the pre-pass and AO kept as
// intermediates) and returns the blurred AO (RGBA8, AO in every channel, 1 off the skin).
sim::RenderTarget ssao_passes(const GpuScene& scene, const PipelineConfig& config, FrameOutput& out,
                              sim::Gpu& gpu);

// The AO pass's taps: `taps` on a Vogel spiral over a disc of kSsaoRadiusMm (focal_uv and
// noise_uv are the frame's to set).
// The disc's radius on the skin: the scale of the nose, the eye sockets and the lips' creases
// (a face-scale AO).
inline constexpr float kSsaoRadiusMm = 12.0f;
shaders::SsaoUniforms ssao_uniforms(int taps);

// The programs the passes run, the AO pass with `taps` taps.
std::vector<sim::NamedProfile> ssao_programs(int taps);

}  // namespace skinsim::pipeline

// Frames of the comparison techniques (docs/techniques.md). Each ends with the `skin`
// framebuffer render; the multi-pass ones render their intermediate buffers first.
#pragma once

#include "pipeline/frame.h"

namespace skinsim::pipeline {

// skin (pre-integrated LUT, one pass)
FrameOutput render_preintegrated_frame(const GpuScene& scene, const PipelineConfig& config,
                                       sim::Gpu& gpu);
// skin (wrap lighting, one pass)
FrameOutput render_wrap_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu);
// diffuse -> sss -> skin
FrameOutput render_burley_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu);
// diffuse -> sss_h -> sss_v -> skin
FrameOutput render_ssss_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu);
// uv_irradiance -> (uv_blur_<i>_h, uv_blur_<i>_v) for i = 1..5 -> uv_combine -> skin
FrameOutput render_texture_space_frame(const GpuScene& scene, const PipelineConfig& config,
                                       sim::Gpu& gpu);

}  // namespace skinsim::pipeline

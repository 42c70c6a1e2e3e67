// Small frames of a small head on the emulated GPU, for the technique tests: fast enough
// to render many per test.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "pipeline/frame.h"
#include "pipeline/gpu_scene.h"

namespace skinsim::pipeline::testing {

// The built-in head with 4000 triangles and 256-texel textures (built once).
const GpuScene& small_scene();

// 256x192, the technique's knobs at small sizes (texture-space 128, 8 Burley taps).
PipelineConfig small_config(const std::string& technique);

FrameOutput render(const PipelineConfig& config);

// The skin draw of the frame's final `skin` render (not the background or eyes).
const sim::DrawCounters& skin_draw(const FrameOutput& out);

// Mean colour of the frame's centre region (the face).
glm::vec3 centre_mean(const sim::RenderTarget& frame);

}  // namespace skinsim::pipeline::testing

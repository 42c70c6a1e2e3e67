// One frame of a skin technique on the emulated GPU: what every technique produces.
#pragma once

#include <string>
#include <vector>

#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"
#include "sim/counters.h"
#include "sim/gpu.h"
#include "sim/render_target.h"

namespace skinsim::pipeline {

// An intermediate render target worth looking at, with the factor that maps its stored
// values to a viewable PNG.
struct NamedTarget {
  std::string name;  // file stem, e.g. "irradiance"
  sim::RenderTarget target;
  float display_scale = 1.0f;
};

struct FrameOutput {
  View view;
  bool lod = false;  // the single-pass distant-skin shader ran
  // Set when the automatic choice took the single-pass shader for distance: says the camera
  // distance, lod_distance_m and the units that related them.
  std::string lod_notice;
  std::vector<sim::PassCounters> passes;
  sim::RenderTarget frame;  // the final image (display-encoded RGBA8)
  std::vector<NamedTarget> intermediates;
  float blur_sigma_pixels = 0.0f;  // screen-space blur width per iteration, buffer texels
};

// Renders one frame of `config.technique` (config validated, resolution resolved).
FrameOutput render_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu);

// Render resolution for a config: its own, or the given default (the device's display).
std::pair<int, int> render_size(const PipelineConfig& config, int default_width,
                                int default_height);

}  // namespace skinsim::pipeline

// One frame of a skin technique on the emulated GPU: what every technique produces.
#pragma once

#include <map>
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
  std::vector<sim::PassCounters> passes;
  sim::RenderTarget frame;  // the final image (display-encoded RGBA8)
  std::vector<NamedTarget> intermediates;
  // What the technique decided for this frame, by name, for result.json's "technique"
  // object (mobile: lod_shader 0 or 1, blur_sigma_texels).
  std::map<std::string, double> decisions;
  // Said to the user as warnings: a choice the technique made that the user may not expect
  // (mobile: the LOD shader taken for distance, with the distance, threshold and units).
  std::vector<std::string> notices;
};

// Renders one frame of `config.technique` (config validated, resolution resolved).
FrameOutput render_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu);

// Render resolution for a config: its own, or the given default (the device's display).
std::pair<int, int> render_size(const PipelineConfig& config, int default_width,
                                int default_height);

}  // namespace skinsim::pipeline

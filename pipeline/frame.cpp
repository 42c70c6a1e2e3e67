#include "pipeline/frame.h"

#include "pipeline/frame_lights.h"
#include "pipeline/technique.h"

namespace skinsim::pipeline {

FrameOutput render_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu) {
  config.validate();
  if (config.width <= 0) throw ConfigError("render resolution must be resolved before rendering");
  std::vector<sim::PassCounters> light_passes;  // the shadow pass, when there are shadows
  const FrameLights lights(scene, config, gpu, light_passes);
  FrameOutput out = find_technique(config.technique).render(scene, config, lights, gpu);
  out.passes.insert(out.passes.begin(), light_passes.begin(), light_passes.end());
  if (const sim::RenderTarget* shadow_map = lights.shadow_map()) {
    out.intermediates.push_back({"shadow_map", *shadow_map, 1.0f});
  }
  return out;
}

std::pair<int, int> render_size(const PipelineConfig& config, int default_width,
                                int default_height) {
  if (config.width > 0) return {config.width, config.height};
  return {default_width, default_height};
}

}  // namespace skinsim::pipeline

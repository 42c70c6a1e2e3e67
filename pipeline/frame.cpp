#include "pipeline/frame.h"

#include "pipeline/technique.h"

namespace skinsim::pipeline {

FrameOutput render_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu) {
  config.validate();
  if (config.width <= 0) throw ConfigError("render resolution must be resolved before rendering");
  return find_technique(config.technique).render(scene, config, gpu);
}

std::pair<int, int> render_size(const PipelineConfig& config, int default_width,
                                int default_height) {
  if (config.width > 0) return {config.width, config.height};
  return {default_width, default_height};
}

}  // namespace skinsim::pipeline

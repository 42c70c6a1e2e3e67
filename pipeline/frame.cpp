#include "pipeline/frame.h"

#include "pipeline/skin_pipeline.h"

namespace skinsim::pipeline {

FrameOutput render_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu) {
  config.validate();
  if (config.width <= 0) throw ConfigError("render resolution must be resolved before rendering");
  switch (config.technique) {
    case Technique::kMobile:
      return render_mobile_frame(scene, config, gpu, MobileMode::kAuto);
    case Technique::kLod:
      return render_mobile_frame(scene, config, gpu, MobileMode::kForceLod);
  }
  throw ConfigError("technique not implemented");
}

}  // namespace skinsim::pipeline

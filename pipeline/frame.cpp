#include "pipeline/frame.h"

#include "pipeline/skin_pipeline.h"
#include "pipeline/techniques/techniques.h"

namespace skinsim::pipeline {

FrameOutput render_frame(const GpuScene& scene, const PipelineConfig& config, sim::Gpu& gpu) {
  config.validate();
  if (config.width <= 0) throw ConfigError("render resolution must be resolved before rendering");
  switch (config.technique) {
    case Technique::kMobile:
      return render_mobile_frame(scene, config, gpu, MobileMode::kAuto);
    case Technique::kLod:
      return render_mobile_frame(scene, config, gpu, MobileMode::kForceLod);
    case Technique::kPreintegrated:
      return render_preintegrated_frame(scene, config, gpu);
    case Technique::kWrap:
      return render_wrap_frame(scene, config, gpu);
    case Technique::kBurley:
      return render_burley_frame(scene, config, gpu);
    case Technique::kSsss:
      return render_ssss_frame(scene, config, gpu);
    case Technique::kTextureSpace:
      return render_texture_space_frame(scene, config, gpu);
  }
  throw ConfigError("technique not implemented");
}

}  // namespace skinsim::pipeline

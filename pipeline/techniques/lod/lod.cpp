// `lod`: the mobile pipeline's single-pass distant-skin shader, at any distance.
#include "pipeline/shader_variants.h"
#include "pipeline/shaders/skin.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/mobile/mobile_frame.h"

namespace skinsim::pipeline {

namespace {

FrameOutput render_lod(const GpuScene& scene, const PipelineConfig& config,
                       const FrameLights& lights, sim::Gpu& gpu) {
  return render_mobile_frame(scene, config, lights, gpu, MobileMode::kForceLod);
}

std::vector<sim::NamedProfile> lod_programs() {
  return specular_variants<shaders::SkinLodFS>();
}

}  // namespace

const TechniqueSpec& lod_technique() {
  static const TechniqueSpec spec{
      .name = "lod",
      .passes = "skin",
      .summary = "the mobile pipeline's single-pass distant-skin shader, at any distance",
      .knobs = {},
      .render = render_lod,
      .shaders = lod_programs,
      .host_ns_per_pixel = 480,
  };
  return spec;
}

}  // namespace skinsim::pipeline

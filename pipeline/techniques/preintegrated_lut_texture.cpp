#include "pipeline/techniques/preintegrated_lut_texture.h"

#include "pipeline/bake/preintegrated_lut.h"
#include "pipeline/knob_types.h"

namespace skinsim::pipeline {

sim::RenderTarget preintegrated_lut_target(const PipelineConfig& cfg) {
  bake::PreintegratedLutParams params;
  params.width = cfg.preintegrated.lut_width;
  params.height = cfg.preintegrated.lut_height;
  const bake::PreintegratedLut lut = bake::bake_preintegrated_lut(params);
  sim::RenderTarget t("preintegrated_lut", lut.width, lut.height, sim::TexelFormat::kRGBA8);
  for (std::size_t i = 0; i < lut.rgb.size(); ++i) {
    t.pixels[i] = sim::quantize(glm::vec4(lut.rgb[i], 1.0f), sim::TexelFormat::kRGBA8);
  }
  return t;
}

KnobSpec preintegrated_lut_knob() {
  return size_knob("preintegrated_lut", "--preintegrated-lut",
                   "Pre-integrated diffusion LUT size (N.L x curvature)",
                   {&PipelineConfig::preintegrated, &PreintegratedParams::lut_width},
                   {&PipelineConfig::preintegrated, &PreintegratedParams::lut_height}, 4, 1024);
}

}  // namespace skinsim::pipeline

#include "pipeline/brdf_lut_texture.h"

namespace skinsim::pipeline {

bake::BrdfLutParams brdf_lut_params(const PipelineConfig& c) {
  bake::BrdfLutParams p;
  p.width = c.lut_width;
  p.height = c.lut_height;
  p.m1 = c.lobe1.roughness;
  p.m2 = c.lobe2.roughness;
  p.weight1 = c.lobe1.weight;
  p.weight2 = c.lobe2.weight;
  p.rho_s = c.specular_intensity;
  return p;
}

BrdfLutTexture BrdfLutTexture::bake(const PipelineConfig& config) {
  const bake::LutFormat format = config.lut_format == sim::TexelFormat::kRGBA16F
                                     ? bake::LutFormat::kRGBA16F
                                     : bake::LutFormat::kRGBA8;
  bake::BrdfLut stored = bake::quantize(bake::bake_brdf_lut(brdf_lut_params(config)), format);
  std::vector<sim::MipLevel> levels;
  for (const bake::LutLevel& level : stored.levels) {
    levels.push_back({level.width, level.height, level.texels});
  }
  sim::Texture2D texture("brdf_lut", std::move(levels), config.lut_format,
                         {sim::Filter::kTrilinear, sim::Wrap::kClamp});
  return BrdfLutTexture(std::move(stored), std::move(texture));
}

void BrdfLutTexture::write_png(const std::string& path) const {
  bake::write_lut_png(stored_, path);
}

}  // namespace skinsim::pipeline

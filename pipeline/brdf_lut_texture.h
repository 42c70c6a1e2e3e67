// The BRDF LUT of a pipeline config as a GPU texture: baked (pipeline/bake), quantised to
// the config's texel format, with roughness varying along its mip chain.
#pragma once

#include <string>

#include "pipeline/bake/brdf_lut.h"
#include "pipeline/config.h"
#include "sim/texture.h"

namespace skinsim::pipeline {

// The LUT baker's parameters implied by a pipeline config (size, lobes, rho_s).
bake::BrdfLutParams brdf_lut_params(const PipelineConfig& config);

class BrdfLutTexture {
 public:
  static BrdfLutTexture bake(const PipelineConfig& config);
  const sim::Texture2D& texture() const { return texture_; }
  // Writes level 0 as stored (quantised to the format) as a PNG a user can open.
  void write_png(const std::string& path) const;

 private:
  BrdfLutTexture(bake::BrdfLut stored, sim::Texture2D texture)
      : stored_(std::move(stored)), texture_(std::move(texture)) {}
  bake::BrdfLut stored_;
  sim::Texture2D texture_;
};

}  // namespace skinsim::pipeline

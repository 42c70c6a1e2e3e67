// The BRDF LUT of a pipeline config as a GPU texture: baked (pipeline/bake), quantised to
// the config's texel format, with roughness varying along its mip chain.
#pragma once

#include <memory>
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
  // The LUT of `config`, baked once per process for each distinct (parameters, format): an
  // application bakes it offline or at load, not per frame, so frames and sweep points that
  // share a LUT share one bake. Thread-safe; the result is immutable.
  static std::shared_ptr<const BrdfLutTexture> shared(const PipelineConfig& config);
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

// The pre-integrated technique's own knobs (preintegrated.cpp binds them), nested in
// PipelineConfig as `preintegrated`. urp reads the same diffusion LUT, so it shares the LUT's
// size (techniques/preintegrated_lut_texture.h).
#pragma once

namespace skinsim::pipeline {

// Where the pre-integrated shader gets surface curvature: baked offline per vertex
// (smoothed, stored in a UV-space texture) or from screen-space derivatives (noisy on
// low-poly meshes: constant per triangle).
enum class CurvatureSource { kVertex, kDerivatives };

struct PreintegratedParams {
  int lut_width = 64;   // diffusion LUT: N.L axis
  int lut_height = 64;  // diffusion LUT: curvature axis
  CurvatureSource curvature = CurvatureSource::kVertex;
  bool shadow_scatter = true;  // Penner's penumbra scattering
};

}  // namespace skinsim::pipeline

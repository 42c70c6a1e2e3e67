// The mobile technique's own knobs (mobile.cpp binds them to rows of the knob table), nested
// in PipelineConfig as `mobile`; lod renders through the same frame (mobile_frame.h).
#pragma once

#include <optional>

namespace skinsim::pipeline {

struct MobileParams {
  // Integration (irradiance) buffer size per axis, as a fraction of the render resolution.
  float scale = 0.5f;
  int blur_iterations = 1;
  // Standard deviation of the screen-space diffusion blur in millimetres on the skin; by
  // default derived from the six-Gaussian profile (diffusion.h).
  std::optional<float> blur_width_mm;
  float normal_offset_mm = 1.0f;  // irradiance-pass vertex push along the normal
  // 0 = blur taps ignore depth (GPU Pro 5); > 0 = taps on a surface this many mm nearer or
  // farther than the centre fade out (the irradiance buffer's alpha carries depth).
  float blur_follow_mm = 0.0f;
  float lod_distance_m = 2.0f;  // beyond this camera distance the single-pass shader runs
};

}  // namespace skinsim::pipeline

// The pre-integrated (N.L, curvature) LUT as the techniques that read it (preintegrated, urp)
// bind it, and the knob that sizes it, one row shared by both.
#pragma once

#include "pipeline/config.h"
#include "pipeline/knob.h"
#include "sim/render_target.h"

namespace skinsim::pipeline {

// The LUT as the GPU stores it: linear RGB in RGBA8 (values are in [0, 1]), bilinear,
// clamped; row 0 (flat skin) at v = 0. Baked at the config's preintegrated_lut size.
sim::RenderTarget preintegrated_lut_target(const PipelineConfig& config);

// `preintegrated_lut`: the LUT's size (N.L x curvature).
KnobSpec preintegrated_lut_knob();

}  // namespace skinsim::pipeline

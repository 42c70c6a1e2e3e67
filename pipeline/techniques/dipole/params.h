// The dipole technique's own knob (dipole.cpp binds it), nested in PipelineConfig as `dipole`.
#pragma once

namespace skinsim::pipeline {

// Size of the dipole shader's uniform tap arrays (a vec2 offset and an area per tap: one
// uniform vector).
inline constexpr int kMaxDipoleSamples = 64;

struct DipoleParams {
  int samples = 30;  // taps per pixel, the centre included (the Unity article's 30 directions)
};

}  // namespace skinsim::pipeline

// The wrap technique's own knob (wrap.cpp binds it), nested in PipelineConfig as `wrap`.
#pragma once

namespace skinsim::pipeline {

struct WrapParams {
  float amount = 0.5f;  // light-wrap amount w: diffuse = max(0, (N.L + w) / (1 + w))
};

}  // namespace skinsim::pipeline

// The light, framing, shadow and transmission rows of the knob table (knob.h).
#pragma once

#include <vector>

#include "pipeline/knob.h"

namespace skinsim::pipeline {

std::vector<KnobSpec> light_knobs();

}  // namespace skinsim::pipeline

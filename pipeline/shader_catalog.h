// Every shader the pipelines use, instantiated with default uniforms, for `skinsim shaders`.
#pragma once

#include <vector>

#include "sim/op_profile.h"

namespace skinsim::pipeline {

std::vector<sim::NamedProfile> shader_catalog();

}  // namespace skinsim::pipeline

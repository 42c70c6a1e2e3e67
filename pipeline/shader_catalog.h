// Every shader program the techniques run, instantiated with default uniforms, with the
// techniques that run it: `skinsim shaders`.
#pragma once

#include <string>
#include <vector>

#include "shading/op_profile.h"

namespace skinsim::pipeline {

struct CatalogEntry {
  sim::NamedProfile program;
  std::vector<std::string> techniques;  // registry order
};

// The programs every technique's framebuffer render draws (surface vertex shader, eyes,
// background), then each technique's own (TechniqueSpec::shaders) in registry order; a
// program several techniques run is listed once.
std::vector<CatalogEntry> shader_catalog();

}  // namespace skinsim::pipeline

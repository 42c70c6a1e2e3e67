// Shader programs as the shader report lists them: a technique's TechniqueSpec::shaders
// instantiates each program it can run with default uniforms.
#pragma once

#include <vector>

#include "pipeline/config.h"
#include "shading/op_profile.h"
#include "sim/program.h"

namespace skinsim::pipeline {

template <class Program>
sim::NamedProfile profile_entry(const Program& p) {
  return {p->name(), p->profile()};
}

template <class FS>
sim::NamedProfile fragment_entry(const typename FS::Uniforms& u = {}) {
  return profile_entry(sim::make_fragment_program<FS>(u));
}

// A skin shader at mediump (the skin_precision knob), listed beside its highp self.
template <class FS>
sim::NamedProfile mediump_fragment_entry(const typename FS::Uniforms& u = {}) {
  return profile_entry(sim::make_fragment_program<FS>(u, sim::Precision::kMediump));
}

template <class VS>
sim::NamedProfile vertex_entry(const typename VS::Uniforms& u = {}) {
  return profile_entry(sim::make_vertex_program<VS>(u));
}

// A skin shader with each specular model, gamma 2.0, and the default one at mediump.
template <template <GammaMode, SpecularModel> class Shader>
std::vector<sim::NamedProfile> specular_variants() {
  constexpr GammaMode kSquare = GammaMode::kSquare;
  return {fragment_entry<Shader<kSquare, SpecularModel::kKsLut>>(),
          mediump_fragment_entry<Shader<kSquare, SpecularModel::kKsLut>>(),
          fragment_entry<Shader<kSquare, SpecularModel::kKs>>(),
          fragment_entry<Shader<kSquare, SpecularModel::kGgx>>(),
          fragment_entry<Shader<kSquare, SpecularModel::kDualGgx>>()};
}

}  // namespace skinsim::pipeline

// The framebuffer render every comparison technique ends with, named `skin` like the
// mobile pipeline's so budgets and charts compare like with like: background, eyes and
// skin in one render (no render-target switch between them), the skin drawn with the
// technique's own fragment program and extra textures.
#pragma once

#include <functional>
#include <memory>

#include "pipeline/config.h"
#include "pipeline/frame_lights.h"
#include "pipeline/gpu_scene.h"
#include "pipeline/shaders/specular.h"
#include "sim/gpu.h"

namespace skinsim::pipeline {

// The skin shaders' uniforms for one material: the frame's lights, eye, albedo factor, the
// layer split, the config's specular lobes and intensity, and the technique knobs.
shaders::TechniqueUniforms technique_uniforms(const View& view, const PipelineConfig& config,
                                              const FrameLights& lights,
                                              const GpuMaterial& material);

// Sets a skin draw's fragment program and its textures beyond albedo, normal map and
// environment (which the pass binds) for one skin material.
using SkinShading = std::function<void(const GpuMaterial&, sim::DrawCall&)>;

// `msaa`: samples per pixel (PipelineConfig::msaa), resolved into `frame`.
sim::PassCounters skin_framebuffer_pass(const GpuScene& scene, const View& view,
                                        const FrameLights& lights, Transmission transmission,
                                        const SkinShading& shading, int msaa,
                                        sim::RenderTarget& frame, sim::Gpu& gpu);

// Calls f(std::integral_constant<GammaMode, g>, std::integral_constant<SpecularModel, s>)
// for the config's gamma and specular model: picks the shader instantiation.
template <class F>
auto with_gamma_and_specular(const PipelineConfig& config, F&& f) {
  const auto with_spec = [&](auto gamma) {
    switch (config.specular) {
      case SpecularModel::kKs:
        return f(gamma, std::integral_constant<SpecularModel, SpecularModel::kKs>{});
      case SpecularModel::kGgx:
        return f(gamma, std::integral_constant<SpecularModel, SpecularModel::kGgx>{});
      case SpecularModel::kDualGgx:
        return f(gamma, std::integral_constant<SpecularModel, SpecularModel::kDualGgx>{});
      case SpecularModel::kKsLut:
        break;
    }
    return f(gamma, std::integral_constant<SpecularModel, SpecularModel::kKsLut>{});
  };
  if (config.gamma == GammaMode::kSquare) {
    return with_spec(std::integral_constant<GammaMode, GammaMode::kSquare>{});
  }
  return with_spec(std::integral_constant<GammaMode, GammaMode::kSrgb>{});
}

}  // namespace skinsim::pipeline

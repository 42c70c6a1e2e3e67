// `wrap`: light wrapping, one pass: the cheapest baseline.
#include "pipeline/shaders/wrap.h"

#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/skin_pass.h"

namespace skinsim::pipeline {

namespace {

FrameOutput render_wrap(const GpuScene& gs, const PipelineConfig& cfg, const FrameLights& lights,
                        sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  const auto brdf_lut = brdf_lut_for(cfg);
  const auto shading = [&](const GpuMaterial& mat, sim::DrawCall& d) {
    const shaders::TechniqueUniforms u = technique_uniforms(out.view, cfg, lights, mat);
    d.fragment_program = with_gamma_and_specular(cfg, [&](auto gamma, auto spec) {
      return sim::make_fragment_program<shaders::WrapFS<gamma(), spec()>>(u, cfg.skin_precision);
    });
    bind_brdf_lut(brdf_lut, d);
  };
  out.passes.push_back(skin_framebuffer_pass(gs, out.view, lights, Transmission::kComputedHere,
                                             shading, cfg.msaa, out.frame, gpu));
  return out;
}

std::vector<sim::NamedProfile> wrap_programs() {
  return specular_variants<shaders::WrapFS>();
}

}  // namespace

const TechniqueSpec& wrap_technique() {
  static const TechniqueSpec spec{
      .name = "wrap",
      .passes = "skin",
      .summary = "light wrapping: the cheapest baseline",
      .knobs = {real_knob("wrap", "--wrap",
                          "Light-wrap amount w: diffuse = max(0, (N.L + w) / (1 + w))",
                          {&PipelineConfig::wrap, &WrapParams::amount}, {0.0, 1.0})},
      .render = render_wrap,
      .shaders = wrap_programs,
      .host_ns_per_pixel = 640,
  };
  return spec;
}

}  // namespace skinsim::pipeline

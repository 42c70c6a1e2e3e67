// `lambert`: Lambert diffuse and the shared specular, one pass, no subsurface scattering. The
// worked example of docs/adding-a-technique.md: a folder and a registry line.
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/lambert/lambert_fs.h"
#include "pipeline/techniques/skin_pass.h"

namespace skinsim::pipeline {

namespace {

FrameOutput render(const GpuScene& gs, const PipelineConfig& cfg, const FrameLights& lights,
                   sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  const auto brdf_lut = brdf_lut_for(cfg);
  const auto shading = [&](const GpuMaterial& mat, sim::DrawCall& d) {
    const shaders::TechniqueUniforms u = technique_uniforms(out.view, cfg, lights, mat);
    d.fragment_program = with_gamma_and_specular(cfg, [&](auto gamma, auto spec) {
      return sim::make_fragment_program<shaders::LambertFS<gamma(), spec()>>(u, cfg.skin_precision);
    });
    bind_brdf_lut(brdf_lut, d);
  };
  out.passes.push_back(skin_framebuffer_pass(gs, out.view, lights, Transmission::kComputedHere,
                                             shading, cfg.msaa, out.frame, gpu));
  return out;
}

std::vector<sim::NamedProfile> programs() {
  return specular_variants<shaders::LambertFS>();
}

}  // namespace

const TechniqueSpec& lambert_technique() {
  static const TechniqueSpec spec{
      .name = "lambert",
      .passes = "skin",
      .summary = "Lambert diffuse, no subsurface scattering: the floor the others improve on",
      .knobs = {},
      .render = render,
      .shaders = programs,
      // wrap's figure: the same single pass with one add and one multiply fewer per light.
      .host_ns_per_pixel = 640,
  };
  return spec;
}

}  // namespace skinsim::pipeline

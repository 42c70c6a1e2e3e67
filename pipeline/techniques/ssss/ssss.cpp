// `ssss`: Jimenez's separable screen-space subsurface scattering (2015) at full resolution:
// diffuse -> sss_h -> sss_v -> skin.
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/kernels.h"
#include "pipeline/techniques/screen_diffusion_passes.h"

namespace skinsim::pipeline {

namespace {

FrameOutput render_ssss(const GpuScene& gs, const PipelineConfig& cfg, const FrameLights& lights,
                        sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  sim::RenderTarget diffuse = screen_buffer("diffuse", cfg);
  sim::RenderTarget horizontal = screen_buffer("sss_h", cfg);
  sim::RenderTarget diffused = screen_buffer("diffused", cfg);
  out.passes.push_back(diffuse_pass(gs, out.view, lights, diffuse, gpu));
  if (out.view.skin_visible) {
    const SeparableKernel kernel = separable_kernel();
    shaders::SsssBlurFS::Uniforms u;
    static_cast<shaders::ScreenKernelUniforms&>(u) =
        kernel_uniforms(out.view, gs.scene().units_per_mm);
    u.offsets_mm = kernel.offsets_mm;
    u.weights = kernel.weights;
    u.axis = {1.0f, 0.0f};
    out.passes.push_back(kernel_pass("sss_h", kernel_program<shaders::SsssBlurFSFor>(out.view, u),
                                     diffuse, horizontal, out.view, gpu));
    u.axis = {0.0f, 1.0f};
    out.passes.push_back(kernel_pass("sss_v", kernel_program<shaders::SsssBlurFSFor>(out.view, u),
                                     horizontal, diffused, out.view, gpu));
  }
  finish_screen_diffusion_frame(gs, cfg, lights, std::move(diffuse), std::move(diffused), out, gpu);
  return out;
}

std::vector<sim::NamedProfile> ssss_programs() {
  std::vector<sim::NamedProfile> list = screen_diffusion_programs();
  for (const sim::NamedProfile& kernel :
       {fragment_entry<shaders::SsssBlurFS>(), fragment_entry<shaders::SsssBlurOrthoFS>()}) {
    list.push_back(kernel);
  }
  return list;
}

}  // namespace

const TechniqueSpec& ssss_technique() {
  static const TechniqueSpec spec{
      .name = "ssss",
      .passes = "diffuse, sss_h, sss_v, skin",
      .summary = "Jimenez separable SSS (2015) at full resolution",
      .knobs = {},
      .render = render_ssss,
      .shaders = ssss_programs,
      .host_ns_per_pixel = 3000,
  };
  return spec;
}

}  // namespace skinsim::pipeline

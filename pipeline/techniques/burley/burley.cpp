// `burley`: Burley normalized diffusion in screen space at full resolution, importance-sampled
// taps in one 2D pass (Golubev 2018): diffuse -> sss -> skin.
#include <fmt/format.h>

#include <algorithm>

#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/kernels.h"
#include "pipeline/techniques/screen_diffusion_passes.h"

namespace skinsim::pipeline {

namespace {

FrameOutput render_burley(const GpuScene& gs, const PipelineConfig& cfg, const FrameLights& lights,
                          sim::Gpu& gpu) {
  return one_kernel_frame(gs, cfg, lights, gpu, [&](const View& view) {
    const BurleyKernel kernel =
        burley_kernel(cfg.burley.samples, cfg.burley.distance_mm.value_or(burley_distance_fit()));
    shaders::BurleyFS::Uniforms u;
    static_cast<shaders::ScreenKernelUniforms&>(u) = kernel_uniforms(view, gs.scene().units_per_mm);
    u.count = cfg.burley.samples;
    std::copy(kernel.offsets_mm.begin(), kernel.offsets_mm.end(), u.offsets_mm.begin());
    std::copy(kernel.weights.begin(), kernel.weights.end(), u.weights.begin());
    return kernel_program<shaders::BurleyFSFor>(view, u);
  });
}

std::vector<sim::NamedProfile> burley_programs() {
  shaders::BurleyFS::Uniforms taps;  // the profile counts the taps: the default count
  taps.count = PipelineConfig{}.burley.samples;
  std::vector<sim::NamedProfile> list = screen_diffusion_programs();
  for (const sim::NamedProfile& kernel :
       {fragment_entry<shaders::BurleyFS>(taps), fragment_entry<shaders::BurleyOrthoFS>(taps)}) {
    list.push_back(kernel);
  }
  return list;
}

}  // namespace

const TechniqueSpec& burley_technique() {
  static const TechniqueSpec spec{
      .name = "burley",
      .passes = "diffuse, sss, skin",
      .summary = "Burley normalized diffusion in screen space, importance-sampled (Golubev 2018)",
      .knobs = {integer_knob("burley_samples", "--burley-samples", "Burley diffusion taps",
                             {&PipelineConfig::burley, &BurleyParams::samples}, 4,
                             kMaxBurleySamples),
                optional_rgb_knob("burley_distance_mm", "--burley-distance-mm",
                                  "Burley scattering distance per channel in mm (auto: fitted to "
                                  "the six-Gaussian profile)",
                                  {&PipelineConfig::burley, &BurleyParams::distance_mm},
                                  {0.01, 20.0})},
      .render = render_burley,
      .shaders = burley_programs,
      .host_ns_per_pixel = 2100,
  };
  return spec;
}

}  // namespace skinsim::pipeline

// `burley`: Burley normalized diffusion in screen space at full resolution, importance-sampled
// taps in one 2D pass (Golubev 2018): diffuse -> sss -> skin.
#include <fmt/format.h>

#include <algorithm>

#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/kernels.h"
#include "pipeline/techniques/screen_diffusion_passes.h"

namespace skinsim::pipeline {

namespace {

FrameOutput render(const GpuScene& gs, const PipelineConfig& cfg, sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  sim::RenderTarget diffuse = screen_buffer("diffuse", cfg);
  sim::RenderTarget diffused = screen_buffer("diffused", cfg);
  out.passes.push_back(diffuse_pass(gs, out.view, diffuse, gpu));
  if (out.view.skin_visible) {
    const BurleyKernel kernel =
        burley_kernel(cfg.burley_samples, cfg.burley_distance_mm.value_or(burley_distance_fit()));
    shaders::BurleyFS::Uniforms u;
    static_cast<shaders::ScreenKernelUniforms&>(u) =
        kernel_uniforms(out.view, gs.scene().units_per_mm);
    u.count = cfg.burley_samples;
    std::copy(kernel.offsets_mm.begin(), kernel.offsets_mm.end(), u.offsets_mm.begin());
    std::copy(kernel.weights.begin(), kernel.weights.end(), u.weights.begin());
    out.passes.push_back(kernel_pass("sss", kernel_program<shaders::BurleyFSFor>(out.view, u),
                                     diffuse, diffused, out.view, gpu));
  }
  finish_screen_diffusion_frame(gs, cfg, std::move(diffuse), std::move(diffused), out, gpu);
  return out;
}

std::vector<sim::NamedProfile> programs() {
  shaders::BurleyFS::Uniforms taps;  // the profile counts the taps: the default count
  taps.count = PipelineConfig{}.burley_samples;
  std::vector<sim::NamedProfile> list = screen_diffusion_programs();
  for (const sim::NamedProfile& kernel :
       {fragment_entry<shaders::BurleyFS>(taps), fragment_entry<shaders::BurleyOrthoFS>(taps)}) {
    list.push_back(kernel);
  }
  return list;
}

KnobSpec distance_knob() {
  KnobSpec k;
  k.name = "burley_distance_mm";
  k.flag = "--burley-distance-mm";
  k.values = "r,g,b in [0.01, 20] mm, or auto";
  k.help = "Burley scattering distance per channel (auto: fitted to the six-Gaussian profile)";
  k.set = [](PipelineConfig& c, const std::string& text) {
    if (text == "auto") {
      c.burley_distance_mm.reset();
    } else {
      c.burley_distance_mm = parse_knob_rgb("burley_distance_mm", text);
    }
  };
  k.get = [](const PipelineConfig& c) {
    if (!c.burley_distance_mm) return std::string("auto");
    const glm::vec3 d = *c.burley_distance_mm;
    return fmt::format("{},{},{}", d.r, d.g, d.b);
  };
  k.invalid = [](const PipelineConfig& c) -> std::string {
    if (!c.burley_distance_mm) return "";
    const glm::vec3 d = *c.burley_distance_mm;
    const Interval range{0.01, 20.0};
    if (range.contains(d.r) && range.contains(d.g) && range.contains(d.b)) return "";
    return fmt::format(
        "burley_distance_mm must be in [0.01, 20] mm per channel, got {:g},{:g},{:g}", d.r, d.g,
        d.b);
  };
  return k;
}

}  // namespace

const TechniqueSpec& burley_technique() {
  static const TechniqueSpec spec{
      .name = "burley",
      .passes = "diffuse, sss, skin",
      .summary = "Burley normalized diffusion in screen space, importance-sampled (Golubev 2018)",
      .knobs = {integer_knob("burley_samples", "--burley-samples", "Burley diffusion taps",
                             &PipelineConfig::burley_samples, 4, kMaxBurleySamples),
                distance_knob()},
      .render = render,
      .shaders = programs,
  };
  return spec;
}

}  // namespace skinsim::pipeline

// `dipole`: Jensen et al. 2001's dipole diffusion evaluated per pixel over a disc of taps in
// screen space, as the Unity article does (30 taps): diffuse -> sss -> skin. The offline
// reference's BSSRDF run in a fragment shader, priced on the device (docs/techniques.md).
#include "pipeline/shaders/dipole.h"

#include <algorithm>
#include <numbers>

#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/kernels.h"
#include "pipeline/techniques/screen_diffusion_passes.h"

namespace skinsim::pipeline {

namespace {

// The kernel's uniforms for `samples` taps of Jensen's Skin1 (bake/dipole.h).
shaders::DipoleUniforms dipole_uniforms(int samples) {
  const bake::DipoleTerms terms = bake::dipole_terms(bake::jensen_skin1());
  const DipoleKernel kernel = dipole_kernel(samples, terms);
  shaders::DipoleUniforms u;
  u.profile = {terms.z_real, terms.z_virtual, terms.sigma_tr,
               terms.alpha_prime / (4.0f * std::numbers::pi_v<float>)};
  u.count = samples;
  std::copy(kernel.offsets_mm.begin(), kernel.offsets_mm.end(), u.offsets_mm.begin());
  std::copy(kernel.areas_mm2.begin(), kernel.areas_mm2.end(), u.areas_mm2.begin());
  return u;
}

FrameOutput render_dipole(const GpuScene& gs, const PipelineConfig& cfg, const FrameLights& lights,
                          sim::Gpu& gpu) {
  return one_kernel_frame(gs, cfg, lights, gpu, [&](const View& view) {
    shaders::DipoleUniforms u = dipole_uniforms(cfg.dipole.samples);
    u.focal_uv = kernel_uniforms(view, gs.scene().units_per_mm).focal_uv;
    u.noise_uv = interleaved_noise_uv(cfg);
    return kernel_program<shaders::DipoleFSFor>(view, u);
  });
}

std::vector<sim::NamedProfile> dipole_programs() {
  // The profile counts the taps: the default count.
  const shaders::DipoleUniforms taps = dipole_uniforms(PipelineConfig{}.dipole.samples);
  std::vector<sim::NamedProfile> list = screen_diffusion_programs();
  list.push_back(fragment_entry<shaders::DipoleFS>(taps));
  list.push_back(fragment_entry<shaders::DipoleOrthoFS>(taps));
  return list;
}

}  // namespace

const TechniqueSpec& dipole_technique() {
  static const TechniqueSpec spec{
      .name = "dipole",
      .passes = "diffuse, sss, skin",
      .summary =
          "Jensen et al. 2001 dipole evaluated per pixel over a disc of taps in screen "
          "space (Unity article)",
      .knobs = {integer_knob("dipole_samples", "--dipole-samples",
                             "Dipole taps per pixel, the centre included (the article uses 30)",
                             {&PipelineConfig::dipole, &DipoleParams::samples}, 4,
                             kMaxDipoleSamples)},
      .render = render_dipole,
      .shaders = dipole_programs,
      // Measured 9870 ns against burley's 3380 in the same loaded session (burley's spec:
      // 2100), so scaled to the others' conditions.
      .host_ns_per_pixel = 6100,
  };
  return spec;
}

}  // namespace skinsim::pipeline

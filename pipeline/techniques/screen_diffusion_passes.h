// The passes the full-resolution screen-space diffusion techniques (burley, ssss) share: a
// `diffuse` pass that stores irradiance and view distance in mm (shaders/screen_diffusion.h),
// and kernel passes over the skin's screen rectangle.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/config.h"
#include "pipeline/frame.h"
#include "pipeline/frame_lights.h"
#include "pipeline/gpu_scene.h"
#include "pipeline/shaders/screen_diffusion.h"
#include "sim/gpu.h"

namespace skinsim::pipeline {

// Irradiance values reach ~2x the key light: halve them to view the buffers.
inline constexpr float kScreenBufferDisplayScale = 0.5f;

// Screen-space buffers are RGBA16F: irradiance above 1 and view distance in mm
// (EXT_color_buffer_half_float, available on the SGX under iOS).
sim::RenderTarget screen_buffer(const char* name, const PipelineConfig& cfg);

sim::PassCounters diffuse_pass(const GpuScene& gs, const View& view, const FrameLights& lights,
                               sim::RenderTarget& target, sim::Gpu& gpu);

shaders::ScreenKernelUniforms kernel_uniforms(const View& view, float units_per_mm);

// The noise_uv of interleaved_gradient_angle (shaders/screen_diffusion.h) for the frame's size.
inline glm::vec2 interleaved_noise_uv(const PipelineConfig& cfg) {
  return {0.06711056f * static_cast<float>(cfg.width),
          0.00583715f * static_cast<float>(cfg.height)};
}

// The perspective or orthographic program of a kernel (shaders/screen_diffusion.h).
template <template <bool> class Kernel, class Uniforms>
std::shared_ptr<const sim::FragmentProgram> kernel_program(const View& view, const Uniforms& u) {
  if (view.orthographic) return sim::make_fragment_program<Kernel<true>>(u);
  return sim::make_fragment_program<Kernel<false>>(u);
}

// The end of a screen-space diffusion frame: the `skin` render reading `diffused`, and both
// buffers kept as intermediates for viewing.
void finish_screen_diffusion_frame(const GpuScene& gs, const PipelineConfig& cfg,
                                   const FrameLights& lights, sim::RenderTarget diffuse,
                                   sim::RenderTarget diffused, FrameOutput& out, sim::Gpu& gpu);

// A whole frame with one kernel pass, `sss`: diffuse -> sss -> skin (burley, dipole). `kernel`
// makes the pass's program for the frame's view (run only when skin is visible).
using KernelProgramFor =
    std::function<std::shared_ptr<const sim::FragmentProgram>(const View& view)>;
FrameOutput one_kernel_frame(const GpuScene& gs, const PipelineConfig& cfg,
                             const FrameLights& lights, sim::Gpu& gpu,
                             const KernelProgramFor& kernel);

// The programs every screen-space diffusion technique runs besides its kernel: the diffuse
// pass (perspective and orthographic), the kernel quad's vertex shader and the skin render.
std::vector<sim::NamedProfile> screen_diffusion_programs();

// A kernel pass over the skin's screen rectangle reading `source`.
sim::PassCounters kernel_pass(const std::string& name,
                              std::shared_ptr<const sim::FragmentProgram> program,
                              const sim::RenderTarget& source, sim::RenderTarget& target,
                              const View& view, sim::Gpu& gpu);

}  // namespace skinsim::pipeline

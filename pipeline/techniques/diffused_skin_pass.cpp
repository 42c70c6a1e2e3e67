#include "pipeline/techniques/diffused_skin_pass.h"

#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/skin_pass.h"

namespace skinsim::pipeline {

namespace {

template <shaders::DiffusionSource kSource>
std::shared_ptr<const sim::FragmentProgram> diffused_skin_program(
    const PipelineConfig& config, const shaders::TechniqueUniforms& u) {
  return with_gamma_and_specular(config, [&](auto gamma, auto spec) {
    return sim::make_fragment_program<shaders::DiffusedSkinFS<gamma(), spec(), kSource>>(
        u, config.skin_precision);
  });
}

}  // namespace

sim::PassCounters diffused_skin_pass(const GpuScene& scene, const View& view,
                                     const PipelineConfig& config, const FrameLights& lights,
                                     shaders::DiffusionSource source,
                                     const sim::RenderTarget& diffused, sim::RenderTarget& frame,
                                     sim::Gpu& gpu) {
  const auto brdf_lut = brdf_lut_for(config);
  const sim::Texture2D buffer =
      sim::texture_view(diffused, {sim::Filter::kBilinear, sim::Wrap::kClamp});
  const auto shading = [&](const GpuMaterial& mat, sim::DrawCall& d) {
    const shaders::TechniqueUniforms u = technique_uniforms(view, config, lights, mat);
    d.fragment_program = source == shaders::DiffusionSource::kScreen
                             ? diffused_skin_program<shaders::DiffusionSource::kScreen>(config, u)
                             : diffused_skin_program<shaders::DiffusionSource::kUv>(config, u);
    d.textures.textures[shaders::TechniqueBindings::kDiffusion] = &buffer;
    bind_brdf_lut(brdf_lut, d);
  };
  return skin_framebuffer_pass(scene, view, lights, Transmission::kComputedElsewhere, shading,
                               config.msaa, frame, gpu);
}

}  // namespace skinsim::pipeline

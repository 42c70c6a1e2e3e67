// `texture-space`: texture-space diffusion (d'Eon & Luebke, GPU Gems 3 ch. 14): irradiance in the
// skin's UV layout, one incremental Gaussian blur per profile term, a weighted combine, and the
// `skin` render reading the result with the mesh UV (shaders/texture_space.h).
#include "pipeline/shaders/texture_space.h"

#include <fmt/format.h>

#include "pipeline/blur_pass.h"
#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/shaders/blur.h"
#include "pipeline/shaders/diffused_skin.h"
#include "pipeline/shaders/screen_diffusion.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/diffused_skin_pass.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/kernels.h"
#include "pipeline/techniques/screen_quad.h"
#include "pipeline/techniques/skin_pass.h"
#include "pipeline/techniques/uv_layout.h"

namespace skinsim::pipeline {

namespace {

using scene::MaterialKind;

// RGBA16F, as d'Eon & Luebke's irradiance textures: irradiance above 1 without a range
// scale, and the blur chain's repeated resolves do not accumulate 8-bit rounding.
sim::RenderTarget uv_buffer(const std::string& name, int size) {
  return sim::RenderTarget(name, size, size, sim::TexelFormat::kRGBA16F);
}

sim::PassCounters uv_irradiance_pass(const GpuScene& gs, const FrameLights& lights,
                                     sim::RenderTarget& target, sim::Gpu& gpu) {
  auto vs = sim::make_vertex_program<shaders::UvSpaceVS>(
      {lights.vertex_uniforms(Transmission::kComputedHere)});
  auto fs = sim::make_fragment_program<shaders::UvIrradianceFS>({lights.uniforms()});
  sim::RenderPassDesc pass;
  pass.name = "uv_irradiance";
  pass.color = &target;
  pass.clear_color = glm::vec4(0.0f);  // alpha 0 outside the UV islands
  for (const GpuMesh& m : gs.meshes()) {
    const GpuMaterial& mat = gs.materials()[m.material];
    if (mat.kind != MaterialKind::kSkin) continue;
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.fragment_program = fs;
    d.textures.textures[shaders::UvIrradianceFS::kNormalMap] = mat.normal;
    lights.bind(d);
    d.cull = sim::CullMode::kNone;  // UV islands may be mirrored
    d.depth_test = false;           // islands do not overlap (uv_layout.h)
    d.depth_write = false;
    pass.draws.push_back(d);
  }
  return gpu.execute(pass);
}

FrameOutput render_texture_space(const GpuScene& gs, const PipelineConfig& cfg,
                                 const FrameLights& lights, sim::Gpu& gpu) {
  require_skin_uvs(gs, "texture-space");
  FrameOutput out = start_frame(gs, cfg);
  const int size = cfg.texture_space.size;
  const sim::PixelRect all{0, 0, size, size};
  const TextureSpaceKernel kernel = texture_space_kernel();
  const float texels_per_mm = uv_texels_per_mm(gs, size);

  // terms[0] is the irradiance, terms[i] the irradiance blurred to profile term i.
  std::vector<sim::RenderTarget> terms;
  terms.reserve(shaders::kTextureSpaceTerms);
  terms.push_back(uv_buffer("uv_irradiance", size));
  out.passes.push_back(uv_irradiance_pass(gs, lights, terms[0], gpu));
  sim::RenderTarget ping = uv_buffer("uv_blur_h", size);
  for (int i = 1; i < shaders::kTextureSpaceTerms; ++i) {
    terms.push_back(uv_buffer(fmt::format("uv_blur_{}", i), size));
    const float sigma = kernel.blur_sigma_mm[i] * texels_per_mm;
    out.passes.push_back(
        blur_pass(fmt::format("uv_blur_{}_h", i), terms[i - 1], ping, all, {1, 0}, sigma, gpu));
    out.passes.push_back(
        blur_pass(fmt::format("uv_blur_{}_v", i), ping, terms[i], all, {0, 1}, sigma, gpu));
  }

  sim::RenderTarget combined = uv_buffer("uv_diffused", size);
  {
    std::vector<sim::Texture2D> inputs;
    inputs.reserve(terms.size());
    sim::DrawCall d;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      inputs.push_back(sim::texture_view(terms[i], {sim::Filter::kBilinear, sim::Wrap::kClamp}));
      d.textures.textures[i] = &inputs.back();
    }
    d.vertex_program = sim::make_vertex_program<shaders::QuadVS>({});
    d.fragment_program = sim::make_fragment_program<shaders::UvCombineFS>({kernel.weights});
    out.passes.push_back(quad_pass("uv_combine", std::move(d), combined, all, gpu));
  }

  out.passes.push_back(diffused_skin_pass(gs, out.view, cfg, lights, shaders::DiffusionSource::kUv,
                                          combined, out.frame, gpu));
  out.intermediates.push_back({"uv_irradiance", std::move(terms[0]), 0.5f});
  out.intermediates.push_back({"uv_diffused", std::move(combined), 0.5f});
  return out;
}

std::vector<sim::NamedProfile> texture_space_programs() {
  return {vertex_entry<shaders::UvSpaceVS>(),
          fragment_entry<shaders::UvIrradianceFS>(),
          vertex_entry<shaders::BlurVS>(),
          fragment_entry<shaders::BlurFS>(),
          vertex_entry<shaders::QuadVS>(),
          fragment_entry<shaders::UvCombineFS>(),
          fragment_entry<shaders::DiffusedSkinFS<GammaMode::kSquare, SpecularModel::kKsLut,
                                                 shaders::DiffusionSource::kUv>>(),
          mediump_fragment_entry<shaders::DiffusedSkinFS<GammaMode::kSquare, SpecularModel::kKsLut,
                                                         shaders::DiffusionSource::kUv>>()};
}

}  // namespace

const TechniqueSpec& texture_space_technique() {
  static const TechniqueSpec spec{
      .name = "texture-space",
      .passes = "uv_irradiance, uv_blur_{1..5}_{h,v}, uv_combine, skin",
      .summary = "d'Eon & Luebke texture-space diffusion (GPU Gems 3 ch. 14)",
      .knobs = {integer_knob("texture_space_size", "--texture-space-size",
                             "Texture-space diffusion buffer size per axis",
                             {&PipelineConfig::texture_space, &TextureSpaceParams::size}, 64, 4096,
                             true)},
      .render = render_texture_space,
      .shaders = texture_space_programs,
      // Its 1024^2 texture-space passes do not scale with the output: the average per
      // output pixel at 2048x1536 (9.3 s) rather than a slope.
      .host_ns_per_pixel = 3000,
  };
  return spec;
}

}  // namespace skinsim::pipeline

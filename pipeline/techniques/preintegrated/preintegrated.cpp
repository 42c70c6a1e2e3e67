// `preintegrated`: Penner & Borshukov pre-integrated skin (GPU Pro 2, 2011), one pass: diffuse
// from a (N.L, curvature) LUT, curvature baked per vertex or from screen-space derivatives.
#include "pipeline/shaders/preintegrated.h"

#include "pipeline/bake/preintegrated_lut.h"
#include "pipeline/bake/shadow_scatter_lut.h"
#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/preintegrated_lut_texture.h"
#include "pipeline/techniques/skin_pass.h"
#include "pipeline/techniques/uv_layout.h"

namespace skinsim::pipeline {

namespace {

// Resolution of the baked curvature texture: curvature is smooth by construction (baked
// from vertices, then smoothed), so a small texture holds it.
constexpr int kCurvatureTextureSize = 256;

// Penner's penumbra-scattering LUT for this frame's penumbra width (bake/shadow_scatter_lut.h),
// RGBA8, 64 x 1.
constexpr int kShadowLutWidth = 64;
sim::Texture2D shadow_scatter_texture(float penumbra_mm) {
  std::vector<glm::vec4> texels;
  for (const glm::vec3& v : bake::shadow_scatter_lut(kShadowLutWidth, penumbra_mm)) {
    texels.emplace_back(v, 1.0f);
  }
  return sim::Texture2D("shadow_scatter_lut", kShadowLutWidth, 1, texels, sim::TexelFormat::kRGBA8,
                        {sim::Filter::kBilinear, sim::Wrap::kClamp}, false);
}

FrameOutput render_preintegrated(const GpuScene& gs, const PipelineConfig& cfg,
                                 const FrameLights& lights, sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  const auto brdf_lut = brdf_lut_for(cfg);
  sim::RenderTarget lut_target = preintegrated_lut_target(cfg);
  const sim::Texture2D lut =
      sim::texture_view(lut_target, {sim::Filter::kBilinear, sim::Wrap::kClamp});
  const float max_curvature = bake::PreintegratedLutParams{}.max_curvature_per_mm;
  std::optional<sim::Texture2D> curvature;
  if (cfg.preintegrated.curvature == CurvatureSource::kVertex) {
    require_skin_uvs(gs, "preintegrated (curvature vertex)");
    curvature = curvature_texture(gs, kCurvatureTextureSize, max_curvature);
  }
  const bool shadow_scatter = cfg.preintegrated.shadow_scatter && lights.uniforms().shadows;
  // Baked only when a frame reads it.
  std::optional<sim::Texture2D> shadow_lut;
  if (shadow_scatter) shadow_lut = shadow_scatter_texture(lights.penumbra_mm());
  const auto shading = [&](const GpuMaterial& mat, sim::DrawCall& d) {
    shaders::TechniqueUniforms u = technique_uniforms(out.view, cfg, lights, mat);
    u.shadow_scatter = shadow_scatter;
    // Texel centres: entry i at visibility i / (width - 1).
    u.shadow_lut_scale = static_cast<float>(kShadowLutWidth - 1) / kShadowLutWidth;
    u.shadow_lut_offset = 0.5f / kShadowLutWidth;
    if (shadow_lut) d.textures.textures[shaders::LightBindings::kShadowLut] = &*shadow_lut;
    // Derivatives give curvature in 1/world unit: times units_per_mm is 1/mm.
    u.curvature_scale = gs.scene().units_per_mm / max_curvature;
    d.fragment_program = with_gamma_and_specular(cfg, [&](auto gamma, auto spec) {
      if (cfg.preintegrated.curvature == CurvatureSource::kVertex) {
        return sim::make_fragment_program<
            shaders::PreintegratedFS<gamma(), spec(), CurvatureSource::kVertex>>(
            u, cfg.skin_precision);
      }
      return sim::make_fragment_program<
          shaders::PreintegratedFS<gamma(), spec(), CurvatureSource::kDerivatives>>(
          u, cfg.skin_precision);
    });
    d.textures.textures[shaders::TechniqueBindings::kPreintegratedLut] = &lut;
    if (curvature) d.textures.textures[shaders::TechniqueBindings::kCurvature] = &*curvature;
    bind_brdf_lut(brdf_lut, d);
  };
  out.passes.push_back(skin_framebuffer_pass(gs, out.view, lights, Transmission::kComputedHere,
                                             shading, cfg.msaa, out.frame, gpu));
  out.intermediates.push_back({"preintegrated_lut", std::move(lut_target), 1.0f});
  return out;
}

std::vector<sim::NamedProfile> preintegrated_programs() {
  constexpr GammaMode kSquare = GammaMode::kSquare;
  constexpr SpecularModel kKsLut = SpecularModel::kKsLut;
  return {
      fragment_entry<shaders::PreintegratedFS<kSquare, kKsLut, CurvatureSource::kVertex>>(),
      fragment_entry<shaders::PreintegratedFS<kSquare, kKsLut, CurvatureSource::kDerivatives>>(),
      mediump_fragment_entry<
          shaders::PreintegratedFS<kSquare, kKsLut, CurvatureSource::kVertex>>()};
}

KnobSpec shadow_scatter_knob() {
  KnobSpec k = switch_knob("shadow_scatter", "--shadow-scatter",
                           "Penner's shadow penumbra scattering: the filtered shadow through a "
                           "LUT that widens and reddens the penumbra (one dependent read)",
                           {&PipelineConfig::preintegrated, &PreintegratedParams::shadow_scatter});
  k.applies = [](const PipelineConfig& c) { return c.shadows; };
  return k;
}

}  // namespace

const TechniqueSpec& preintegrated_technique() {
  static const TechniqueSpec spec{
      .name = "preintegrated",
      .passes = "skin",
      .summary = "Penner & Borshukov pre-integrated skin (GPU Pro 2, 2011)",
      .knobs =
          {
              preintegrated_lut_knob(),
              choice_knob("curvature", "--curvature",
                          "Curvature source: baked per vertex and smoothed, or screen-space "
                          "derivatives (constant per triangle on low-poly meshes)",
                          "vertex or derivatives",
                          {&PipelineConfig::preintegrated, &PreintegratedParams::curvature},
                          parse_curvature, curvature_name),
              shadow_scatter_knob(),
          },
      .render = render_preintegrated,
      .shaders = preintegrated_programs,
      .host_ns_per_pixel = 850,
  };
  return spec;
}

}  // namespace skinsim::pipeline

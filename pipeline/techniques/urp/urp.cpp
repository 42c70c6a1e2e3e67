// `urp`: the URP PBR skin shader article's skin (docs/techniques.md, urp): screen-space AO in
// its own passes (ssao_passes.h), then one skin pass with pre-integrated diffuse, detail
// normals, dual-lobe GGX and image-based specular, AO with the shadow folded in, the shadow
// tint and a clear coat (shaders/urp.h): depth_normal -> ssao -> ssao_h -> ssao_v -> skin.
#include "pipeline/shaders/urp.h"

#include <cmath>
#include <optional>

#include "pipeline/bake/ambient_occlusion.h"
#include "pipeline/bake/pore_normals.h"
#include "pipeline/bake/preintegrated_lut.h"
#include "pipeline/knob_types.h"
#include "pipeline/shader_variants.h"
#include "pipeline/technique.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/preintegrated_lut_texture.h"
#include "pipeline/techniques/skin_pass.h"
#include "pipeline/techniques/urp/ssao_passes.h"
#include "pipeline/techniques/uv_layout.h"

namespace skinsim::pipeline {

namespace {

// The generated pore map (bake/pore_normals.h), RGBA8, mipmapped (the blurred detail normal
// reads a coarse mip), repeating. Baked once: it depends on nothing.
const sim::Texture2D& pore_normal_texture() {
  static const sim::Texture2D texture = [] {
    const bake::PoreNormalParams params;
    std::vector<glm::vec4> texels;
    for (const glm::vec3& n : bake::bake_pore_normals(params)) {
      texels.emplace_back(n * 0.5f + 0.5f, 1.0f);
    }
    return sim::Texture2D("pore_normals", params.size, params.size, texels,
                          sim::TexelFormat::kRGBA8, {sim::Filter::kTrilinear, sim::Wrap::kRepeat},
                          true);
  }();
  return texture;
}

// The baked AO: the skin's per-vertex ambient occlusion (bake/ambient_occlusion.h) in its UV
// layout, 512 x 512 (AO varies over millimetres to centimetres).
constexpr int kBakedAoTextureSize = 512;
sim::Texture2D baked_ao_texture(const GpuScene& gs) {
  return vertex_value_texture(gs, "baked_ao", kBakedAoTextureSize, [&](const scene::Mesh& mesh) {
    return bake::bake_ambient_occlusion(gs.rays(), mesh.positions, mesh.normals,
                                        gs.scene().units_per_mm);
  });
}

// Unity's perceptual-roughness-to-mip mapping (UnityStandardUtils / URP ImageBasedLighting:
// mip = r (1.7 - 0.7 r) UNITY_SPECCUBE_LOD_STEPS, r = sqrt(GGX alpha), 6 steps for a 128
// cube): the steps are the cube's mip count less one, as for Unity's cube.
float environment_lod(float alpha, int cube_size) {
  const float r = std::sqrt(alpha);
  const float steps = std::log2(static_cast<float>(cube_size)) - 1.0f;
  return r * (1.7f - 0.7f * r) * steps;
}

shaders::UrpUniforms urp_uniforms(const GpuScene& gs, const PipelineConfig& cfg,
                                  const shaders::TechniqueUniforms& base) {
  shaders::UrpUniforms u;
  static_cast<shaders::TechniqueUniforms&>(u) = base;
  // Derivatives give curvature in 1/world unit: times units_per_mm is 1/mm.
  u.curvature_scale = gs.scene().units_per_mm / bake::PreintegratedLutParams{}.max_curvature_per_mm;
  u.shadow_color = cfg.shadow_tint.value_or(shaders::kShadowSkinColor);
  u.ssao = cfg.urp.ssao;
  u.detail_normals = cfg.urp.detail_normals;
  u.clear_coat = cfg.urp.clear_coat;
  const int cube = gs.environment().size();
  u.lobe1_lod = environment_lod(cfg.lobe1.roughness, cube);
  u.lobe2_lod = environment_lod(cfg.lobe2.roughness, cube);
  u.coat_lod = environment_lod(u.coat_roughness, cube);
  u.lobe1_environment = shaders::environment_lobe(cfg.lobe1.roughness, cfg.lobe1.weight, u.f0);
  u.lobe2_environment = shaders::environment_lobe(cfg.lobe2.roughness, cfg.lobe2.weight, u.f0);
  return u;
}

FrameOutput render_urp(const GpuScene& gs, const PipelineConfig& cfg, const FrameLights& lights,
                       sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  std::optional<sim::RenderTarget> ao;
  if (cfg.urp.ssao && out.view.skin_visible) ao = ssao_passes(gs, cfg, out, gpu);
  std::optional<sim::Texture2D> ao_texture;
  if (ao) ao_texture = sim::texture_view(*ao, {sim::Filter::kNearest, sim::Wrap::kClamp});
  require_skin_uvs(gs, "urp (baked AO)");
  const sim::Texture2D baked_ao = baked_ao_texture(gs);
  sim::RenderTarget lut_target = preintegrated_lut_target(cfg);
  const sim::Texture2D lut =
      sim::texture_view(lut_target, {sim::Filter::kBilinear, sim::Wrap::kClamp});
  const auto shading = [&](const GpuMaterial& mat, sim::DrawCall& d) {
    shaders::UrpUniforms u = urp_uniforms(gs, cfg, technique_uniforms(out.view, cfg, lights, mat));
    u.ssao = ao_texture.has_value();
    if (cfg.gamma == GammaMode::kSquare) {
      d.fragment_program =
          sim::make_fragment_program<shaders::UrpFS<GammaMode::kSquare>>(u, cfg.skin_precision);
    } else {
      d.fragment_program =
          sim::make_fragment_program<shaders::UrpFS<GammaMode::kSrgb>>(u, cfg.skin_precision);
    }
    using B = shaders::UrpBindings;
    // The skin pass binds the cosine-filtered cube at unit 2; urp reads no such cube.
    d.textures.cubes[shaders::TechniqueBindings::kEnvironment] = nullptr;
    d.textures.cubes[B::kEnvironment] = &gs.environment();
    d.textures.textures[B::kBakedAo] = &baked_ao;
    d.textures.textures[B::kPreintegratedLut] = &lut;
    if (cfg.urp.detail_normals) d.textures.textures[B::kDetailNormals] = &pore_normal_texture();
    if (ao_texture) d.textures.textures[B::kAo] = &*ao_texture;
  };
  out.passes.push_back(skin_framebuffer_pass(gs, out.view, lights, Transmission::kComputedHere,
                                             shading, cfg.msaa, out.frame, gpu));
  out.intermediates.push_back({"preintegrated_lut", std::move(lut_target), 1.0f});
  if (ao) out.intermediates.push_back({"ssao_blurred", std::move(*ao), 1.0f});
  return out;
}

std::vector<sim::NamedProfile> urp_programs() {
  std::vector<sim::NamedProfile> list = ssao_programs(PipelineConfig{}.urp.ssao_taps);
  list.push_back(fragment_entry<shaders::UrpFS<GammaMode::kSquare>>());
  list.push_back(mediump_fragment_entry<shaders::UrpFS<GammaMode::kSquare>>());
  return list;
}

}  // namespace

const TechniqueSpec& urp_technique() {
  static const TechniqueSpec spec{
      .name = "urp",
      .passes = "depth_normal, ssao, ssao_h, ssao_v, skin",
      .summary =
          "URP PBR skin shader article: pre-integrated diffuse, dual-lobe GGX and IBL, SSAO "
          "passes, shadow tint, detail normals, clear coat",
      .knobs = {
          preintegrated_lut_knob(),
          [] {
            KnobSpec k = switch_knob("urp_ssao", "--urp-ssao",
                                     "Screen-space AO: a depth/normal pre-pass, the AO pass "
                                     "and a two-pass blur before the skin pass",
                                     {&PipelineConfig::urp, &UrpParams::ssao});
            k.decides = true;  // urp_ssao_taps applies only with it on
            return k;
          }(),
          [] {
            KnobSpec k =
                integer_knob("urp_ssao_taps", "--urp-ssao-taps", "Screen-space AO taps per pixel",
                             {&PipelineConfig::urp, &UrpParams::ssao_taps}, 4, kMaxSsaoTaps);
            k.applies = [](const PipelineConfig& c) { return c.urp.ssao; };
            return k;
          }(),
          switch_knob("urp_detail_normals", "--urp-detail-normals",
                      "Tiling pore detail normals (generated: the scenes have no detail "
                      "map), sharp and blurred: two more reads",
                      {&PipelineConfig::urp, &UrpParams::detail_normals}),
          switch_knob("urp_clear_coat", "--urp-clear-coat",
                      "Clear-coat specular layer over the skin (direct and image-based)",
                      {&PipelineConfig::urp, &UrpParams::clear_coat}),
      },
      .render = render_urp,
      .shaders = urp_programs,
      // Measured 10100 ns against burley's 1620 in the same loaded session (burley's spec:
      // 2100), so scaled to the others' conditions. The AO taps' reach in pixels grows with
      // the resolution, so the slope is steeper than the per-pixel work alone.
      .host_ns_per_pixel = 13100,
      .own_specular = true,
  };
  return spec;
}

}  // namespace skinsim::pipeline

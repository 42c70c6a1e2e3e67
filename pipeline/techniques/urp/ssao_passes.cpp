#include "pipeline/techniques/urp/ssao_passes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pipeline/blur_pass.h"
#include "pipeline/lighting.h"
#include "pipeline/shader_variants.h"
#include "pipeline/shaders/blur.h"
#include "pipeline/shaders/screen_diffusion.h"
#include "pipeline/techniques/screen_diffusion_passes.h"

namespace skinsim::pipeline {

namespace {

// The blur's standard deviation in pixels: enough to even out the per-pixel turned disc.
constexpr float kSsaoBlurSigma = 2.0f;

// The pre-pass: the skin's view-space normal and view depth (mm); 0 where there is no skin.
sim::PassCounters depth_normal_pass(const GpuScene& gs, const PipelineConfig& cfg, const View& view,
                                    sim::RenderTarget& target, sim::Gpu& gpu) {
  const float mm_per_unit = 1.0f / gs.scene().units_per_mm;
  shaders::SurfaceVS::Uniforms vu;
  vu.view_proj = view.view_proj;
  vu.view_depth = true;
  vu.view_depth_plane = glm::vec4(view.forward * mm_per_unit,
                                  -glm::dot(view.forward, view.camera_position) * mm_per_unit);
  const glm::vec3 right = glm::normalize(glm::cross(view.forward, frame_camera(gs, cfg).up));
  const auto fs = sim::make_fragment_program<shaders::DepthNormalFS>(
      {right, glm::cross(right, view.forward), -view.forward});
  const auto vs = sim::make_vertex_program<shaders::PositionNormalVS>(vu);
  sim::RenderPassDesc pass;
  pass.name = "depth_normal";
  pass.color = &target;
  pass.clear_color = glm::vec4(0.0f);
  for (const GpuMesh& m : gs.meshes()) {
    if (gs.materials()[m.material].kind != scene::MaterialKind::kSkin) continue;
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.fragment_program = fs;
    pass.draws.push_back(d);
  }
  return gpu.execute(pass);
}

// `r` grown by `by` pixels on each side, within the target.
sim::PixelRect grown(const sim::PixelRect& r, int by, int width, int height) {
  return {std::max(r.x0 - by, 0), std::max(r.y0 - by, 0), std::min(r.x1 + by, width),
          std::min(r.y1 + by, height)};
}

}  // namespace

shaders::SsaoUniforms ssao_uniforms(int taps) {
  shaders::SsaoUniforms u;
  u.count = taps;
  // A Vogel (golden-angle) spiral: equal-area rings, so each tap stands for the same area.
  const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < taps; ++i) {
    const float r = kSsaoRadiusMm * std::sqrt((static_cast<float>(i) + 0.5f) / taps);
    const float a = golden * static_cast<float>(i);
    u.offsets_mm[i] = r * glm::vec2(std::cos(a), std::sin(a));
  }
  return u;
}

sim::RenderTarget ssao_passes(const GpuScene& gs, const PipelineConfig& cfg, FrameOutput& out,
                              sim::Gpu& gpu) {
  const View& view = out.view;
  sim::RenderTarget depth_normal = screen_buffer("depth_normal", cfg);
  out.passes.push_back(depth_normal_pass(gs, cfg, view, depth_normal, gpu));
  shaders::SsaoUniforms u = ssao_uniforms(cfg.urp.ssao_taps);
  u.focal_uv = kernel_uniforms(view, gs.scene().units_per_mm).focal_uv;
  u.noise_uv = interleaved_noise_uv(cfg);
  sim::RenderTarget ao("ssao", cfg.width, cfg.height, sim::TexelFormat::kRGBA8);
  sim::RenderTarget ao_h("ssao_h", cfg.width, cfg.height, sim::TexelFormat::kRGBA8);
  // The AO and the horizontal blur cover the skin's rectangle grown by the blur's reach, so
  // the blur reads rendered AO (1 off the skin) around the skin.
  const int reach = static_cast<int>(std::ceil(2.5f * kSsaoBlurSigma)) + 1;
  View grown_view = view;
  grown_view.skin_rect = grown(view.skin_rect, reach, cfg.width, cfg.height);
  const sim::PixelRect& area = grown_view.skin_rect;
  out.passes.push_back(kernel_pass("ssao", kernel_program<shaders::SsaoFSFor>(view, u),
                                   depth_normal, ao, grown_view, gpu));
  out.passes.push_back(blur_pass("ssao_h", ao, ao_h, area, {1.0f, 0.0f}, kSsaoBlurSigma, gpu));
  sim::RenderTarget blurred("ssao_blurred", cfg.width, cfg.height, sim::TexelFormat::kRGBA8);
  out.passes.push_back(
      blur_pass("ssao_v", ao_h, blurred, view.skin_rect, {0.0f, 1.0f}, kSsaoBlurSigma, gpu));
  out.intermediates.push_back({"ssao", std::move(ao), 1.0f});
  return blurred;
}

std::vector<sim::NamedProfile> ssao_programs(int taps) {
  const shaders::SsaoUniforms u = ssao_uniforms(taps);
  return {vertex_entry<shaders::PositionNormalVS>(), fragment_entry<shaders::DepthNormalFS>(),
          fragment_entry<shaders::SsaoFS>(u),        fragment_entry<shaders::SsaoOrthoFS>(u),
          vertex_entry<shaders::QuadVS>(),           vertex_entry<shaders::BlurVS>(),
          fragment_entry<shaders::BlurFS>()};
}

}  // namespace skinsim::pipeline

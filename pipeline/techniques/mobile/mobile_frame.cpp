#include "pipeline/techniques/mobile/mobile_frame.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "pipeline/blur_pass.h"
#include "pipeline/diffusion.h"
#include "pipeline/shaders/irradiance.h"
#include "pipeline/shaders/skin.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/skin_pass.h"

namespace skinsim::pipeline {

namespace {

using scene::MaterialKind;

sim::PixelRect scale_rect(const sim::PixelRect& r, float sx, float sy, int w, int h) {
  return {std::clamp(static_cast<int>(std::floor(r.x0 * sx)) - 1, 0, w),
          std::clamp(static_cast<int>(std::floor(r.y0 * sy)) - 1, 0, h),
          std::clamp(static_cast<int>(std::ceil(r.x1 * sx)) + 1, 0, w),
          std::clamp(static_cast<int>(std::ceil(r.y1 * sy)) + 1, 0, h)};
}

// The depth-aware blur's depth code: the skin's distance +-150 mm in 254 steps (1.18 mm).
constexpr float kDepthCodeHalfRangeMm = 150.0f;
constexpr float kMmPerDepthCode = 2.0f * kDepthCodeHalfRangeMm / 254.0f;

sim::PassCounters irradiance_pass(const GpuScene& gs, const View& view, const PipelineConfig& cfg,
                                  const FrameLights& lights, sim::RenderTarget& buffer,
                                  sim::Gpu& gpu) {
  const float mm_per_unit = 1.0f / gs.scene().units_per_mm;
  const float offset = cfg.mobile.normal_offset_mm * gs.scene().units_per_mm;
  // The skin at its true position and depth decides every pixel it covers; the normal offset
  // only dilates coverage into the background, in a second draw behind all skin.
  shaders::SurfaceVS::Uniforms vu{view.view_proj, 0.0f,
                                  lights.vertex_uniforms(Transmission::kComputedHere)};
  shaders::IrradianceFS::Uniforms fu{lights.uniforms()};
  if (cfg.mobile.blur_follow_mm > 0.0f) {
    // View depth in mm: dot(p - camera, forward) / units_per_mm.
    vu.view_depth = true;
    vu.view_depth_plane = glm::vec4(view.forward * mm_per_unit,
                                    -glm::dot(view.forward, view.camera_position) * mm_per_unit);
    fu.depth_code = true;
    fu.depth_near_mm = view.skin_distance * mm_per_unit - kDepthCodeHalfRangeMm;
    fu.inv_depth_range_mm = 1.0f / (2.0f * kDepthCodeHalfRangeMm);
  }
  auto vs = sim::make_vertex_program<shaders::PositionNormalVS>(vu);
  vu.normal_offset = offset;
  auto dilated_vs = sim::make_vertex_program<shaders::DilatedPositionNormalVS>(vu);
  auto fs = sim::make_fragment_program<shaders::IrradianceFS>(fu);
  sim::RenderPassDesc pass;
  pass.name = "irradiance";
  pass.color = &buffer;
  pass.clear_color = glm::vec4(0.0f);  // alpha 0: no skin
  for (const GpuMesh& m : gs.meshes()) {
    if (gs.materials()[m.material].kind != MaterialKind::kSkin) continue;
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.fragment_program = fs;
    lights.bind(d);
    pass.draws.push_back(d);
    if (offset > 0.0f) {
      d.vertex_program = dilated_vs;
      pass.draws.push_back(d);
    }
  }
  return gpu.execute(pass);
}

sim::PassCounters framebuffer_pass(const GpuScene& gs, const View& view, const PipelineConfig& cfg,
                                   const FrameLights& lights,
                                   const std::shared_ptr<const BrdfLutTexture>& lut,
                                   const sim::Texture2D* irradiance, bool lod,
                                   sim::RenderTarget& frame, sim::Gpu& gpu) {
  const auto shading = [&](const GpuMaterial& mat, sim::DrawCall& d) {
    const shaders::TechniqueUniforms u = technique_uniforms(view, cfg, lights, mat);
    d.fragment_program = with_gamma_and_specular(cfg, [&](auto gamma, auto spec) {
      if (lod)
        return sim::make_fragment_program<shaders::SkinLodFS<gamma(), spec()>>(u,
                                                                               cfg.skin_precision);
      return sim::make_fragment_program<shaders::SkinFS<gamma(), spec()>>(u, cfg.skin_precision);
    });
    d.textures.textures[shaders::SkinBindings::kIrradiance] = irradiance;
    bind_brdf_lut(lut, d);
  };
  // The LOD shader computes transmission itself; otherwise it is in the buffer.
  return skin_framebuffer_pass(gs, view, lights,
                               lod ? Transmission::kComputedHere : Transmission::kComputedElsewhere,
                               shading, cfg.msaa, frame, gpu);
}

}  // namespace

FrameOutput render_mobile_frame(const GpuScene& gs, const PipelineConfig& cfg,
                                const FrameLights& lights, sim::Gpu& gpu, MobileMode mode) {
  const std::shared_ptr<const BrdfLutTexture> lut = brdf_lut_for(cfg);
  FrameOutput out;
  out.view = make_view(gs, cfg);
  out.frame = sim::RenderTarget("frame", cfg.width, cfg.height, sim::TexelFormat::kRGBA8);
  const float units_per_m = gs.scene().units_per_mm * 1000.0f;
  const bool lod = mode == MobileMode::kForceLod || !gs.has_skin() || !out.view.skin_visible ||
                   out.view.skin_distance > cfg.mobile.lod_distance_m * units_per_m;
  out.decisions["lod_shader"] = lod ? 1.0 : 0.0;
  if (lod && mode != MobileMode::kForceLod && !gs.has_skin()) {
    out.notices.push_back(
        "the single-pass LOD shader was chosen: no material is classified as skin (name your "
        "skin materials with --skin-materials, or 'all')");
  } else if (lod && mode != MobileMode::kForceLod && out.view.skin_visible) {
    out.notices.push_back(fmt::format(
        "the single-pass LOD shader was chosen: camera distance {:.3g} m > lod_distance_m {:.3g} "
        "m at units_per_mm {:.4g}; if the scene is not in metres pass --units-per-mm (or raise "
        "--lod-distance)",
        out.view.skin_distance / units_per_m, cfg.mobile.lod_distance_m, gs.scene().units_per_mm));
  }

  if (lod) {
    out.passes.push_back(
        framebuffer_pass(gs, out.view, cfg, lights, lut, nullptr, true, out.frame, gpu));
    return out;
  }

  const int bw = std::max(1, static_cast<int>(std::lround(cfg.width * cfg.mobile.scale)));
  const int bh = std::max(1, static_cast<int>(std::lround(cfg.height * cfg.mobile.scale)));
  sim::RenderTarget irradiance("irradiance", bw, bh, sim::TexelFormat::kRGBA8);
  out.passes.push_back(irradiance_pass(gs, out.view, cfg, lights, irradiance, gpu));

  // Blur width: the profile's wide-layer sigma in mm, projected at the skin's distance, in
  // buffer texels; k iterations of sigma/sqrt(k) compose to the same total variance.
  const float sigma_mm = cfg.mobile.blur_width_mm.value_or(skin_layer_split().wide_sigma_mm);
  const float sigma_full = sigma_mm * out.view.pixels_per_mm(gs.scene().units_per_mm);
  const float blur_sigma = sigma_full * static_cast<float>(bw) / static_cast<float>(cfg.width) /
                           std::sqrt(static_cast<float>(cfg.mobile.blur_iterations));
  out.decisions["blur_sigma_texels"] = blur_sigma;
  const sim::PixelRect rect = scale_rect(out.view.skin_rect, static_cast<float>(bw) / cfg.width,
                                         static_cast<float>(bh) / cfg.height, bw, bh);
  sim::RenderTarget ping("blur_h", bw, bh, sim::TexelFormat::kRGBA8);
  sim::RenderTarget blurred("blurred", bw, bh, sim::TexelFormat::kRGBA8);
  // Depth-aware taps (blur_follow_mm): the tent's half-width in depth codes; the last axis
  // writes the premultiplied light and coverage the skin pass reads.
  const auto follow = [&](bool last_axis) -> std::optional<BlurFollow> {
    if (cfg.mobile.blur_follow_mm <= 0.0f) return std::nullopt;
    return BlurFollow{255.0f * kMmPerDepthCode / cfg.mobile.blur_follow_mm, last_axis};
  };
  const sim::RenderTarget* source = &irradiance;
  for (int i = 0; i < cfg.mobile.blur_iterations; ++i) {
    const std::string suffix = i == 0 ? "" : std::to_string(i + 1);  // blur_h, blur_h2, ...
    out.passes.push_back(
        blur_pass("blur_h" + suffix, *source, ping, rect, {1, 0}, blur_sigma, gpu, follow(false)));
    out.passes.push_back(blur_pass("blur_v" + suffix, ping, blurred, rect, {0, 1}, blur_sigma, gpu,
                                   follow(i + 1 == cfg.mobile.blur_iterations)));
    source = &blurred;
  }
  const sim::Texture2D blurred_texture =
      sim::texture_view(blurred, {sim::Filter::kBilinear, sim::Wrap::kClamp});
  out.passes.push_back(
      framebuffer_pass(gs, out.view, cfg, lights, lut, &blurred_texture, false, out.frame, gpu));
  // Stored irradiance is divided by kIrradianceRange: scale back to show the light.
  out.intermediates.push_back({"irradiance", std::move(irradiance), shaders::kIrradianceRange});
  out.intermediates.push_back({"blurred", std::move(blurred), shaders::kIrradianceRange});
  return out;
}

}  // namespace skinsim::pipeline

#include "pipeline/techniques/screen_diffusion_passes.h"

#include "pipeline/shader_variants.h"
#include "pipeline/shaders/diffused_skin.h"
#include "pipeline/techniques/diffused_skin_pass.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/screen_quad.h"
#include "pipeline/techniques/skin_pass.h"

namespace skinsim::pipeline {

namespace {

// A tap on a surface this much nearer or farther than the centre (mm) is fully replaced
// by the centre value: silhouettes (nose against cheek: centimetres) stop the kernel,
// while a surface sloping away across a 4 mm kernel does not.
constexpr float kFollowSurfaceMm = 10.0f;

}  // namespace

sim::RenderTarget screen_buffer(const char* name, const PipelineConfig& cfg) {
  return sim::RenderTarget(name, cfg.width, cfg.height, sim::TexelFormat::kRGBA16F);
}

sim::PassCounters diffuse_pass(const GpuScene& gs, const View& view, const FrameLights& lights,
                               sim::RenderTarget& target, sim::Gpu& gpu) {
  auto vs = sim::make_vertex_program<shaders::SurfaceVS>(
      {view.view_proj, 0.0f, lights.vertex_uniforms(Transmission::kComputedHere)});
  const float mm_per_unit = 1.0f / gs.scene().units_per_mm;
  std::shared_ptr<const sim::FragmentProgram> fs;
  if (view.orthographic) {
    // Depth from the near plane (fragments lie beyond it), plus 1 mm so that skin is > 0.
    const float near_plane_mm =
        (glm::dot(view.forward, view.camera_position) + gs.scene().camera.znear) * mm_per_unit;
    fs = sim::make_fragment_program<shaders::DiffuseDepthOrthoFS>(
        {view.forward * mm_per_unit, 1.0f - near_plane_mm, lights.uniforms()});
  } else {
    fs = sim::make_fragment_program<shaders::DiffuseDepthFS>(
        {view.eye, lights.uniforms(), mm_per_unit});
  }
  sim::RenderPassDesc pass;
  pass.name = "diffuse";
  pass.color = &target;
  pass.clear_color = glm::vec4(0.0f);  // depth 0: no skin
  for (const GpuMesh& m : gs.meshes()) {
    const GpuMaterial& mat = gs.materials()[m.material];
    if (mat.kind != scene::MaterialKind::kSkin) continue;
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.fragment_program = fs;
    d.textures.textures[shaders::DiffuseDepthFS::kNormalMap] = mat.normal;
    lights.bind(d);
    pass.draws.push_back(d);
  }
  return gpu.execute(pass);
}

shaders::ScreenKernelUniforms kernel_uniforms(const View& view, float units_per_mm) {
  shaders::ScreenKernelUniforms k;
  // Perspective: uv per mm at a depth of 1 mm (the shader divides by the depth in mm).
  // Orthographic: uv per mm at every depth.
  const float pixels = view.orthographic ? view.pixels_per_mm(units_per_mm) : view.focal_pixels;
  k.focal_uv =
      glm::vec2(pixels / static_cast<float>(view.width), pixels / static_cast<float>(view.height));
  k.inv_follow_mm = 1.0f / kFollowSurfaceMm;
  return k;
}

// A kernel pass over the skin's screen rectangle reading `source`.
sim::PassCounters kernel_pass(const std::string& name,
                              std::shared_ptr<const sim::FragmentProgram> program,
                              const sim::RenderTarget& source, sim::RenderTarget& target,
                              const View& view, sim::Gpu& gpu) {
  const sim::Texture2D src = sim::texture_view(source, {sim::Filter::kBilinear, sim::Wrap::kClamp});
  sim::DrawCall d;
  d.vertex_program = sim::make_vertex_program<shaders::QuadVS>({});
  d.fragment_program = std::move(program);
  d.textures.textures[0] = &src;
  return quad_pass(name, std::move(d), target, view.skin_rect, gpu);
}

void finish_screen_diffusion_frame(const GpuScene& gs, const PipelineConfig& cfg,
                                   const FrameLights& lights, sim::RenderTarget diffuse,
                                   sim::RenderTarget diffused, FrameOutput& out, sim::Gpu& gpu) {
  out.passes.push_back(diffused_skin_pass(
      gs, out.view, cfg, lights, shaders::DiffusionSource::kScreen, diffused, out.frame, gpu));
  out.intermediates.push_back({"diffuse", std::move(diffuse), kScreenBufferDisplayScale});
  out.intermediates.push_back({"diffused", std::move(diffused), kScreenBufferDisplayScale});
}

FrameOutput one_kernel_frame(const GpuScene& gs, const PipelineConfig& cfg,
                             const FrameLights& lights, sim::Gpu& gpu,
                             const KernelProgramFor& kernel) {
  FrameOutput out = start_frame(gs, cfg);
  sim::RenderTarget diffuse = screen_buffer("diffuse", cfg);
  sim::RenderTarget diffused = screen_buffer("diffused", cfg);
  out.passes.push_back(diffuse_pass(gs, out.view, lights, diffuse, gpu));
  if (out.view.skin_visible) {
    out.passes.push_back(kernel_pass("sss", kernel(out.view), diffuse, diffused, out.view, gpu));
  }
  finish_screen_diffusion_frame(gs, cfg, lights, std::move(diffuse), std::move(diffused), out, gpu);
  return out;
}

std::vector<sim::NamedProfile> screen_diffusion_programs() {
  return {fragment_entry<shaders::DiffuseDepthFS>(), fragment_entry<shaders::DiffuseDepthOrthoFS>(),
          vertex_entry<shaders::QuadVS>(),
          fragment_entry<shaders::DiffusedSkinFS<GammaMode::kSquare, SpecularModel::kKsLut,
                                                 shaders::DiffusionSource::kScreen>>(),
          mediump_fragment_entry<shaders::DiffusedSkinFS<GammaMode::kSquare, SpecularModel::kKsLut,
                                                         shaders::DiffusionSource::kScreen>>()};
}

}  // namespace skinsim::pipeline

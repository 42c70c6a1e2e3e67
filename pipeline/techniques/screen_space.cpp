// The full-resolution screen-space diffusion techniques: Burley (one 2D pass) and
// Jimenez's separable SSS (two 1D passes), both from a `diffuse` pass that stores
// irradiance and view distance (shaders/screen_diffusion.h).
#include <algorithm>

#include "pipeline/shaders/screen_diffusion.h"
#include "pipeline/techniques/diffused_skin_pass.h"
#include "pipeline/techniques/frame_setup.h"
#include "pipeline/techniques/kernels.h"
#include "pipeline/techniques/screen_quad.h"
#include "pipeline/techniques/skin_pass.h"
#include "pipeline/techniques/techniques.h"

namespace skinsim::pipeline {

namespace {

using scene::MaterialKind;

// A tap on a surface this much nearer or farther than the centre (mm) is fully replaced
// by the centre value: silhouettes (nose against cheek: centimetres) stop the kernel,
// while a surface sloping away across a 4 mm kernel does not.
constexpr float kFollowSurfaceMm = 10.0f;

// Screen-space buffers are RGBA16F: irradiance above 1 and view distance in mm
// (EXT_color_buffer_half_float, available on the SGX under iOS).
sim::RenderTarget screen_buffer(const char* name, const PipelineConfig& cfg) {
  return sim::RenderTarget(name, cfg.width, cfg.height, sim::TexelFormat::kRGBA16F);
}

sim::PassCounters diffuse_pass(const GpuScene& gs, const View& view, sim::RenderTarget& target,
                               sim::Gpu& gpu) {
  const SceneLighting light = scene_lighting(gs.scene());
  auto vs = sim::make_vertex_program<shaders::SurfaceVS>({view.view_proj, 0.0f});
  const float mm_per_unit = 1.0f / gs.scene().units_per_mm;
  std::shared_ptr<const sim::FragmentProgram> fs;
  if (view.orthographic) {
    // Depth from the near plane (fragments lie beyond it), plus 1 mm so that skin is > 0.
    const float near_plane_mm =
        (glm::dot(view.forward, view.camera_position) + gs.scene().camera.znear) * mm_per_unit;
    fs = sim::make_fragment_program<shaders::DiffuseDepthOrthoFS>(
        {view.forward * mm_per_unit, 1.0f - near_plane_mm, light.light_dir,
         light.light_radiance, light.ambient});
  } else {
    fs = sim::make_fragment_program<shaders::DiffuseDepthFS>(
        {view.eye, light.light_dir, light.light_radiance, light.ambient, mm_per_unit});
  }
  sim::RenderPassDesc pass;
  pass.name = "diffuse";
  pass.color = &target;
  pass.clear_color = glm::vec4(0.0f);  // depth 0: no skin
  for (const GpuMesh& m : gs.meshes()) {
    const GpuMaterial& mat = gs.materials()[m.material];
    if (mat.kind != MaterialKind::kSkin) continue;
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.fragment_program = fs;
    d.textures.textures[shaders::DiffuseDepthFS::kNormalMap] = mat.normal;
    pass.draws.push_back(d);
  }
  return gpu.execute(pass);
}

shaders::ScreenKernelUniforms kernel_uniforms(const View& view, float units_per_mm) {
  shaders::ScreenKernelUniforms k;
  // Perspective: uv per mm at a depth of 1 mm (the shader divides by the depth in mm).
  // Orthographic: uv per mm at every depth.
  const float pixels = view.orthographic ? view.pixels_per_mm(units_per_mm) : view.focal_pixels;
  k.focal_uv = glm::vec2(pixels / static_cast<float>(view.width),
                         pixels / static_cast<float>(view.height));
  k.inv_follow_mm = 1.0f / kFollowSurfaceMm;
  return k;
}

// The perspective or orthographic program of a kernel (shaders/screen_diffusion.h).
template <template <bool> class Kernel, class Uniforms>
std::shared_ptr<const sim::FragmentProgram> kernel_program(const View& view, const Uniforms& u) {
  if (view.orthographic) return sim::make_fragment_program<Kernel<true>>(u);
  return sim::make_fragment_program<Kernel<false>>(u);
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

// Irradiance values reach ~2x the key light: halve them to view the buffers.
constexpr float kBufferDisplayScale = 0.5f;

}  // namespace

FrameOutput render_burley_frame(const GpuScene& gs, const PipelineConfig& cfg, sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  sim::RenderTarget diffuse = screen_buffer("diffuse", cfg);
  sim::RenderTarget diffused = screen_buffer("diffused", cfg);
  out.passes.push_back(diffuse_pass(gs, out.view, diffuse, gpu));
  if (out.view.skin_visible) {
    const BurleyKernel kernel =
        burley_kernel(cfg.burley_samples, cfg.burley_distance_mm.value_or(burley_distance_fit()));
    shaders::BurleyFS::Uniforms u;
    static_cast<shaders::ScreenKernelUniforms&>(u) = kernel_uniforms(out.view, gs.scene().units_per_mm);
    u.count = cfg.burley_samples;
    std::copy(kernel.offsets_mm.begin(), kernel.offsets_mm.end(), u.offsets_mm.begin());
    std::copy(kernel.weights.begin(), kernel.weights.end(), u.weights.begin());
    out.passes.push_back(kernel_pass("sss", kernel_program<shaders::BurleyFSFor>(out.view, u),
                                     diffuse, diffused, out.view, gpu));
  }
  out.passes.push_back(diffused_skin_pass(gs, out.view, cfg, shaders::DiffusionSource::kScreen,
                                          diffused, out.frame, gpu));
  out.intermediates.push_back({"diffuse", std::move(diffuse), kBufferDisplayScale});
  out.intermediates.push_back({"diffused", std::move(diffused), kBufferDisplayScale});
  return out;
}

FrameOutput render_ssss_frame(const GpuScene& gs, const PipelineConfig& cfg, sim::Gpu& gpu) {
  FrameOutput out = start_frame(gs, cfg);
  sim::RenderTarget diffuse = screen_buffer("diffuse", cfg);
  sim::RenderTarget horizontal = screen_buffer("sss_h", cfg);
  sim::RenderTarget diffused = screen_buffer("diffused", cfg);
  out.passes.push_back(diffuse_pass(gs, out.view, diffuse, gpu));
  if (out.view.skin_visible) {
    const SeparableKernel kernel = separable_kernel();
    shaders::SsssBlurFS::Uniforms u;
    static_cast<shaders::ScreenKernelUniforms&>(u) = kernel_uniforms(out.view, gs.scene().units_per_mm);
    u.offsets_mm = kernel.offsets_mm;
    u.weights = kernel.weights;
    u.axis = {1.0f, 0.0f};
    out.passes.push_back(kernel_pass("sss_h", kernel_program<shaders::SsssBlurFSFor>(out.view, u),
                                     diffuse, horizontal, out.view, gpu));
    u.axis = {0.0f, 1.0f};
    out.passes.push_back(kernel_pass("sss_v", kernel_program<shaders::SsssBlurFSFor>(out.view, u),
                                     horizontal, diffused, out.view, gpu));
  }
  out.passes.push_back(diffused_skin_pass(gs, out.view, cfg, shaders::DiffusionSource::kScreen,
                                          diffused, out.frame, gpu));
  out.intermediates.push_back({"diffuse", std::move(diffuse), kBufferDisplayScale});
  out.intermediates.push_back({"diffused", std::move(diffused), kBufferDisplayScale});
  return out;
}

}  // namespace skinsim::pipeline

#include "pipeline/reference/reference.h"

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "pipeline/bake/brdf_lut.h"
#include "pipeline/bake/skin_profile.h"
#include "pipeline/bake/specular.h"
#include "pipeline/brdf_lut_texture.h"
#include "pipeline/frame_lights.h"
#include "pipeline/reference/ambient_visibility.h"
#include "pipeline/reference/dipole_diffusion.h"
#include "pipeline/reference/gaussian_diffusion.h"
#include "pipeline/reference/gbuffer_shaders.h"
#include "pipeline/reference/pixel_noise.h"
#include "pipeline/reference/shadow_origin.h"
#include "pipeline/shaders/background.h"
#include "pipeline/shaders/eye.h"
#include "sim/gpu.h"
#include "util/srgb.h"

namespace skinsim::pipeline {

namespace {

using scene::MaterialKind;

struct GBuffer {
  sim::RenderTarget position, normal, albedo, vertex_normal, nonskin;
};

template <class FS>
sim::PassCounters gbuffer_pass(
    const GpuScene& gs, const View& view, sim::RenderTarget& target, sim::Gpu& gpu,
    const std::function<typename FS::Uniforms(const GpuMaterial&)>& uniforms) {
  shaders::LightVertexUniforms thickness;  // the baked thickness, for VertexNormalFS
  thickness.shadow_coord = false;
  thickness.thickness = true;
  auto vs = sim::make_vertex_program<shaders::SurfaceVS>({view.view_proj, 0.0f, thickness});
  sim::RenderPassDesc pass;
  pass.name = target.name;
  pass.color = &target;
  for (const GpuMesh& m : gs.meshes()) {
    const GpuMaterial& mat = gs.materials()[m.material];
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.fragment_program = sim::make_fragment_program<FS>(uniforms(mat));
    d.textures.textures[0] = mat.base_color;
    d.textures.textures[1] = mat.normal;
    pass.draws.push_back(d);
  }
  return gpu.execute(pass);
}

float kind_code(MaterialKind k) {
  switch (k) {
    case MaterialKind::kSkin:
      return reference::kKindSkin;
    case MaterialKind::kEye:
      return reference::kKindEye;
    case MaterialKind::kOther:
      break;
  }
  return reference::kKindOther;
}

GBuffer render_gbuffer(const GpuScene& gs, const PipelineConfig& cfg, const View& view,
                       int threads) {
  const int w = cfg.width, h = cfg.height;
  sim::GpuConfig config;
  config.threads = threads;
  sim::Gpu gpu(config);
  GBuffer g{{"ref_position", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_normal", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_albedo", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_vertex_normal", w, h, sim::TexelFormat::kRGBA32F},
            {"ref_nonskin", w, h, sim::TexelFormat::kRGBA32F}};
  gbuffer_pass<reference::PositionFS>(gs, view, g.position, gpu, [](const GpuMaterial& m) {
    return reference::PositionFS::Uniforms{kind_code(m.kind)};
  });
  gbuffer_pass<reference::ShadingNormalFS>(gs, view, g.normal, gpu, [](const GpuMaterial& m) {
    return reference::ShadingNormalFS::Uniforms{m.reflectivity, m.kind == MaterialKind::kSkin};
  });
  gbuffer_pass<reference::AlbedoFS>(gs, view, g.albedo, gpu, [](const GpuMaterial& m) {
    return reference::AlbedoFS::Uniforms{glm::vec3(m.base_color_factor)};
  });
  gbuffer_pass<reference::VertexNormalFS>(gs, view, g.vertex_normal, gpu, [](const GpuMaterial&) {
    return reference::VertexNormalFS::Uniforms{};
  });

  // Eyes and background: the same shaders as the pipelines (not what is studied), in float,
  // with the same shadow map.
  // A fixed, fine shadow map whatever the shadow knobs, so the reference does not depend on
  // them (knob.h: KnobSpec::reference).
  PipelineConfig light_cfg = cfg;
  light_cfg.shadows = true;
  light_cfg.shadow_map_size = 2048;
  light_cfg.shadow_depth = sim::TexelFormat::kDepth24;
  light_cfg.shadow_filter = ShadowFilter::kPcf2x2;
  light_cfg.shadow_taps = 4;
  light_cfg.shadow_tint.reset();
  std::vector<sim::PassCounters> light_passes;
  const FrameLights lights(gs, light_cfg, gpu, light_passes);
  auto vs = sim::make_vertex_program<shaders::SurfaceVS>(
      {view.view_proj, 0.0f, lights.vertex_uniforms(Transmission::kComputedElsewhere)});
  sim::RenderPassDesc pass;
  pass.name = "ref_nonskin";
  pass.color = &g.nonskin;
  pass.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  for (const GpuMesh& m : gs.meshes()) {
    const GpuMaterial& mat = gs.materials()[m.material];
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    d.textures.textures[0] = mat.base_color;
    lights.bind(d);
    const glm::vec3 factor(mat.base_color_factor);
    if (mat.kind == MaterialKind::kEye) {
      shaders::EyeFS::Uniforms u;
      u.eye = view.eye;
      u.lights = lights.uniforms();
      u.albedo_factor = factor;
      d.fragment_program = sim::make_fragment_program<shaders::EyeFS>(u);
      d.textures.cubes[shaders::EyeFS::kEnvironment] = &gs.environment();
    } else {
      d.fragment_program =
          sim::make_fragment_program<shaders::BackgroundFS>({lights.uniforms(), factor});
    }
    pass.draws.push_back(d);
  }
  gpu.execute(pass);
  return g;
}

// Dual-lobe Kelemen/Szirmay-Kalos specular (d'Eon & Luebke, GPU Gems 3, ch. 14), exact.
float ks_specular(const glm::vec3& n, const glm::vec3& l, const glm::vec3& v,
                  const bake::BrdfLutParams& p) {
  return p.weight1 * bake::ks_skin_specular(n, l, v, p.m1, p.rho_s, p.f0) +
         p.weight2 * bake::ks_skin_specular(n, l, v, p.m2, p.rho_s, p.f0);
}

// The hemisphere integrals behind the LUT's B and A channels depend on N.V only; a
// 1024-entry float table, linearly interpolated, stands in for per-pixel integration
// (its interpolation error is far below the 8-bit LUT's quantisation being measured).
class DirectionalTable {
 public:
  explicit DirectionalTable(const bake::BrdfLutParams& p) : entries_(kSize + 1) {
    tbb::parallel_for(0, kSize + 1, [&](int i) {
      const float n_dot_v = std::max(static_cast<float>(i) / kSize, 1e-4f);
      entries_[i] = bake::directional_reflectance(n_dot_v, p.m1, p.m2, p);
    });
  }
  // Fraction of light entering the skin (1 - specular albedo) and lobe-averaged Fresnel.
  void at(float n_dot_v, float& energy, float& fresnel) const {
    const float x = std::clamp(n_dot_v, 0.0f, 1.0f) * kSize;
    const int i = std::min(static_cast<int>(x), kSize - 1);
    const float t = x - static_cast<float>(i);
    const auto& a = entries_[i];
    const auto& b = entries_[i + 1];
    energy = 1.0f - static_cast<float>(a.albedo + (b.albedo - a.albedo) * t);
    fresnel = static_cast<float>(a.fresnel + (b.fresnel - a.fresnel) * t);
  }

 private:
  static constexpr int kSize = 1024;
  std::vector<bake::DirectionalReflectance> entries_;
};

// Fraction of a disc light of angular radius kLightRadiusRad around `l` visible from p:
// kShadowRays rays over the disc (a Fibonacci spiral, rotated per pixel by interleaved
// gradient noise, Jimenez 2014, so that the penumbra's steps become fine noise).
constexpr float kLightRadiusRad = 0.0175f;  // 1 degree: a softbox ~7 cm wide at 2 m
constexpr int kShadowRays = 16;
constexpr float kBackLightDistanceMm = 300.0f;

float visibility(const bake::RayScene& rays, const glm::vec3& p, const glm::vec3& l, int x, int y,
                 float offset, float reach) {
  const glm::vec3 helper = std::abs(l.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, l));
  const glm::vec3 b = glm::cross(l, t);
  const float rotation = 6.2831853f * reference::interleaved_gradient_noise(x, y);
  std::array<glm::vec3, kShadowRays> directions;
  for (int i = 0; i < kShadowRays; ++i) {
    const float r = kLightRadiusRad * std::sqrt((static_cast<float>(i) + 0.5f) / kShadowRays);
    const float phi = 2.39996323f * static_cast<float>(i) + rotation;
    directions[i] = glm::normalize(l + r * (std::cos(phi) * t + std::sin(phi) * b));
  }
  return static_cast<float>(rays.unoccluded(p, directions, offset, reach)) / kShadowRays;
}

// Transmittance of a slab `s` mm thick: the profile's Gaussians, as the pipelines use it
// (shaders/lights.h, Jimenez et al. 2010).
glm::vec3 transmittance(float s_mm) {
  glm::vec3 t(0.0f);
  for (const bake::GaussianTerm& g : bake::skin_gaussians()) {
    t += g.weight * std::exp(-s_mm * s_mm / g.variance_mm2);
  }
  return t;
}

// The lights the reference sees: the frame's ambient, key and back light, and how far each
// light is. The key is distant; the back (rim) light stands 30 cm behind the head, as in a
// studio, between it and any backdrop, which therefore casts no shadow of it.
struct ReferenceLights {
  glm::vec3 ambient{0.0f};
  std::vector<scene::DirectionalLight> lights;
  std::vector<float> reach;
};

ReferenceLights reference_lights(const GpuScene& gs, const PipelineConfig& config) {
  const FrameLighting lighting = frame_lighting(gs, config);
  ReferenceLights out{lighting.ambient, {lighting.key}, {}};
  if (lighting.has_back()) out.lights.push_back(lighting.back);
  out.reach = {std::numeric_limits<float>::infinity(),
               kBackLightDistanceMm * gs.scene().units_per_mm};
  return out;
}

// Calls row(y) for each row of a w x h image, on `threads` threads (0: all).
void for_rows(int h, int threads, const std::function<void(int)>& row) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] { tbb::parallel_for(0, h, row); });
}

// Calls row(y, x_begin, x_end) for each row of each block of pixels of a w x h image.
void for_blocks(int w, int h, int threads, const std::function<void(int, int, int)>& row) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range2d<int>(0, h, 32, 0, w, 128),
                      [&](const tbb::blocked_range2d<int>& block) {
                        for (int y = block.rows().begin(); y < block.rows().end(); ++y) {
                          row(y, block.cols().begin(), block.cols().end());
                        }
                      });
  });
}

// Light reaching the skin: irradiance per pixel, each light's visibility per pixel
// (pixel-major, lights.size() per pixel) and the environment's (ambient_visibility.h).
struct SkinLight {
  std::vector<glm::vec3> irradiance;
  std::vector<float> visible;
  std::vector<glm::vec3> environment_visible;
};

SkinLight light_skin(const GpuScene& gs, const View& view, const GBuffer& g,
                     const ReferenceLights& rl, int threads) {
  const int w = g.position.width, h = g.position.height;
  const std::vector<scene::DirectionalLight>& lights = rl.lights;
  // Shadow rays start this far off the surface (past the triangles they start on).
  const float ray_offset = 0.05f * gs.scene().units_per_mm;
  SkinLight out{std::vector<glm::vec3>(static_cast<size_t>(w) * h, glm::vec3(0.0f)),
                std::vector<float>(static_cast<size_t>(w) * h * lights.size(), 0.0f),
                std::vector<glm::vec3>(static_cast<size_t>(w) * h, glm::vec3(1.0f))};
  const reference::AmbientRays ambient_rays(gs);
  for_rows(h, threads, [&](int y) {
    for (int x = 0; x < w; ++x) {
      if (g.position.at(x, y).w != reference::kKindSkin) continue;
      const glm::vec3 n(g.normal.at(x, y));
      const glm::vec3 p(g.position.at(x, y));
      const glm::vec3 vertex_n(g.vertex_normal.at(x, y));
      // The light's physics, whatever the knobs: visibility is always ray cast and light
      // always crosses thin parts (the shadows and transmission knobs switch the
      // pipelines' approximations of these, measured against this).
      const glm::vec3 origin =
          reference::shadow_ray_origin(gs, view.eye, p, ray_offset) + vertex_n * ray_offset;
      const reference::AmbientVisibility open = ambient_rays.at(origin, vertex_n, x, y, ray_offset);
      out.environment_visible[static_cast<size_t>(y) * w + x] = open.environment;
      glm::vec3 e = rl.ambient * open.ambient;
      for (std::size_t i = 0; i < lights.size(); ++i) {
        const scene::DirectionalLight& light = lights[i];
        const float n_dot_l = glm::dot(n, light.direction);
        if (n_dot_l <= 0.0f) continue;
        const float v =
            visibility(gs.rays(), origin, light.direction, x, y, ray_offset, rl.reach[i]);
        out.visible[(static_cast<size_t>(y) * w + x) * lights.size() + i] = v;
        e += light.radiance * n_dot_l * v;
      }
      glm::vec3 back(0.0f);
      for (const scene::DirectionalLight& light : lights) {
        back += light.radiance * std::clamp(0.3f - glm::dot(vertex_n, light.direction), 0.0f, 1.0f);
      }
      if (back != glm::vec3(0.0f)) e += transmittance(g.vertex_normal.at(x, y).w) * back;
      out.irradiance[static_cast<size_t>(y) * w + x] = e;
    }
  });
  return out;
}

// The reference profile's diffusion of the skin's irradiance.
std::unique_ptr<const SkinDiffusion> skin_diffusion(const PipelineConfig& config, const GBuffer& g,
                                                    const std::vector<glm::vec3>& irradiance,
                                                    const View& view, float units_per_mm) {
  if (config.reference_profile == ReferenceProfile::kDipole) {
    return std::make_unique<const DipoleDiffusion>(g.position, reference::kKindSkin, irradiance,
                                                   view, units_per_mm,
                                                   bake::dipole_terms(bake::jensen_skin1()));
  }
  return std::make_unique<const GaussianDiffusion>(g.position, reference::kKindSkin, irradiance,
                                                   view, units_per_mm);
}

// Shades the reference's pixels from the G-buffer, the diffused light and the lights'
// visibility: the skin's diffuse, the Kelemen/Szirmay-Kalos specular and the environment's
// Fresnel; other surfaces as the G-buffer holds them.
class ReferenceShader {
 public:
  ReferenceShader(const GpuScene& gs, const PipelineConfig& config, const View& view,
                  const GBuffer& g, const ReferenceLights& rl, const SkinLight& light)
      : gs_(gs),
        view_(view),
        g_(g),
        lights_(rl.lights),
        visible_(light.visible),
        environment_visible_(light.environment_visible),
        lut_params_(brdf_lut_params(config)),
        directional_(lut_params_) {}

  void shade(int x, int y, const glm::vec3& diffused, ReferenceFrame& out) const {
    const int w = g_.position.width;
    const glm::vec4 p = g_.position.at(x, y);
    if (p.w != reference::kKindSkin) {
      out.frame.at(x, y) = g_.nonskin.at(x, y);
      return;
    }
    out.skin_mask[static_cast<size_t>(y) * w + x] = 1;
    const glm::vec3 n(g_.normal.at(x, y));
    const float reflectivity = g_.normal.at(x, y).w;
    const glm::vec3 v = view_.to_viewer(glm::vec3(p));
    const float n_dot_v = std::clamp(glm::dot(n, v), 0.0f, 1.0f);
    const glm::vec3 albedo(g_.albedo.at(x, y));
    float energy = 0.0f, fresnel = 0.0f;
    directional_.at(n_dot_v, energy, fresnel);
    const glm::vec3 diffuse = albedo * diffused * energy;
    glm::vec3 specular(0.0f);
    for (std::size_t i = 0; i < lights_.size(); ++i) {
      const scene::DirectionalLight& light = lights_[i];
      if (glm::dot(n, light.direction) <= 0.0f) continue;
      specular += light.radiance * ks_specular(n, light.direction, v, lut_params_) * reflectivity *
                  visible_[(static_cast<size_t>(y) * w + x) * lights_.size() + i];
    }
    const glm::vec3 env =
        reference::sample_cube(gs_.environment_diffuse(), glm::vec3(g_.vertex_normal.at(x, y))) *
        environment_visible_[static_cast<size_t>(y) * w + x];
    const glm::vec3 color = diffuse + specular + env * fresnel * reflectivity;
    out.frame.at(x, y) =
        glm::vec4(srgb_encode(color.r), srgb_encode(color.g), srgb_encode(color.b), 1.0f);
  }

 private:
  const GpuScene& gs_;
  const View& view_;
  const GBuffer& g_;
  const std::vector<scene::DirectionalLight>& lights_;
  const std::vector<float>& visible_;
  const std::vector<glm::vec3>& environment_visible_;
  const bake::BrdfLutParams lut_params_;
  const DirectionalTable directional_;
};

}  // namespace

ReferenceFrame render_reference(const GpuScene& gs, const PipelineConfig& config, int threads) {
  const int w = config.width, h = config.height;
  const View view = make_view(gs, config);
  const GBuffer g = render_gbuffer(gs, config, view, threads);
  const ReferenceLights lights = reference_lights(gs, config);
  const SkinLight light = light_skin(gs, view, g, lights, threads);
  const std::unique_ptr<const SkinDiffusion> diffusion =
      skin_diffusion(config, g, light.irradiance, view, gs.scene().units_per_mm);
  const ReferenceShader shader(gs, config, view, g, lights, light);
  ReferenceFrame out{sim::RenderTarget("reference", w, h, sim::TexelFormat::kRGBA32F),
                     std::vector<std::uint8_t>(static_cast<size_t>(w) * h, 0)};
  // In blocks, not whole rows: a pixel's diffusion reads ~50 rows around it, and a block's
  // rows stay in the core's cache while a whole row's would not.
  for_blocks(w, h, threads, [&](int y, int x_begin, int x_end) {
    std::vector<glm::vec3> diffused(static_cast<std::size_t>(x_end - x_begin));
    diffusion->row(y, x_begin, x_end, diffused.data());
    for (int x = x_begin; x < x_end; ++x) shader.shade(x, y, diffused[x - x_begin], out);
  });
  return out;
}

}  // namespace skinsim::pipeline

#include "pipeline/frame_lights.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/bake/skin_profile.h"
#include "pipeline/shaders/shadow.h"

namespace skinsim::pipeline {

namespace {

struct LightCamera {
  glm::mat4 view_proj{1.0f};
  float texel_world = 0.0f;  // world size of one shadow-map texel
  float depth_range = 1.0f;  // world depth the [0, 1] depth spans
};

// The light-view-space bounds of a box.
Bounds in_view(const Bounds& b, const glm::mat4& view) {
  Bounds r;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y,
                           (i & 4) ? b.hi.z : b.lo.z);
    r.add(glm::vec3(view * glm::vec4(corner, 1.0f)));
  }
  return r;
}

// An orthographic camera looking along -direction whose square view holds the character
// `c` and whose depth range holds every receiver `all` (so a backdrop beyond the character
// compares against the far plane, lit, rather than beyond it).
LightCamera fit_light_camera(const Bounds& c, const Bounds& all, const glm::vec3& direction,
                             int size) {
  const float radius = std::max(glm::length(all.hi - all.lo) * 0.5f, 1e-6f);
  const glm::vec3 up = std::abs(direction.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::mat4 view = glm::lookAt(all.centre() + direction * (2.0f * radius), all.centre(), up);
  const Bounds character = in_view(c, view);
  const Bounds receivers = in_view(all, view);
  const glm::vec3 lo(character.lo.x, character.lo.y, receivers.lo.z);
  const glm::vec3 hi(character.hi.x, character.hi.y, receivers.hi.z);
  // Square texels: the larger extent on both axes, one texel of margin each side.
  const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
  const float texel = extent / static_cast<float>(std::max(size - 2, 1));
  const float half = 0.5f * extent + texel;
  const glm::vec2 mid(0.5f * (lo.x + hi.x), 0.5f * (lo.y + hi.y));
  const float margin = 0.01f * radius;
  const float z_near = -hi.z - margin, z_far = -lo.z + margin;
  LightCamera cam;
  cam.view_proj =
      glm::ortho(mid.x - half, mid.x + half, mid.y - half, mid.y + half, z_near, z_far) * view;
  cam.texel_world = 2.0f * half / static_cast<float>(size);
  cam.depth_range = z_far - z_near;
  return cam;
}

}  // namespace

FrameLights::FrameLights(const GpuScene& gs, const PipelineConfig& cfg, sim::Gpu& gpu,
                         std::vector<sim::PassCounters>& passes)
    : lighting_(frame_lighting(gs, cfg)),
      shadows_(cfg.shadows && !gs.bounds().empty()),
      transmission_(cfg.transmission) {
  shaders::LightUniforms& u = uniforms_;
  u.count = lighting_.has_back() ? 2 : 1;
  u.direction = {lighting_.key.direction, lighting_.back.direction};
  u.radiance = {lighting_.key.radiance, lighting_.back.radiance};
  u.ambient = lighting_.ambient;

  u.transmission = transmission_;
  u.shadows = false;  // until the shadow map below exists
  const auto& gaussians = bake::skin_gaussians();
  for (int i = 0; i < shaders::kTransmittanceTerms; ++i) {
    u.transmittance_weight[i] = gaussians[i].weight;
    u.transmittance_inv_variance[i] = 1.0f / gaussians[i].variance_mm2;
  }
  if (!shadows_) return;

  const int size = cfg.shadow_map_size;
  const LightCamera cam =
      fit_light_camera(gs.character_bounds(), gs.bounds(), lighting_.key.direction, size);
  // Percentage-closer taps on an n x n grid one texel apart, centred on the pixel; tap 0's
  // offset goes into the matrix so that its fetch reads the varying as it is.
  const int n = static_cast<int>(std::lround(std::sqrt(static_cast<float>(cfg.shadow_taps))));
  const float texel_uv = 1.0f / static_cast<float>(size);
  const auto grid = [&](int i) {
    return glm::vec2(static_cast<float>(i % n) - 0.5f * static_cast<float>(n - 1),
                     static_cast<float>(i / n) - 0.5f * static_cast<float>(n - 1)) *
           texel_uv;
  };
  u.shadows = true;
  u.shadow_taps = n * n;
  for (int i = 0; i < u.shadow_taps; ++i) u.shadow_offsets[i] = grid(i) - grid(0);
  u.shadow_tinted = cfg.shadow_tint.has_value();
  u.shadow_tint = cfg.shadow_tint.value_or(glm::vec3(0.0f));

  // Against acne: push the looked-up point 1.5 texels along the normal and compare one
  // texel's worth of depth nearer (the usual normal-offset plus constant bias).
  normal_offset_ = 1.5f * cam.texel_world;
  const float depth_bias = cam.texel_world / cam.depth_range;
  const glm::mat4 to_texture(
      glm::vec4(0.5f, 0.0f, 0.0f, 0.0f), glm::vec4(0.0f, -0.5f, 0.0f, 0.0f),
      glm::vec4(0.0f, 0.0f, 0.5f, 0.0f),
      glm::vec4(0.5f + grid(0).x, 0.5f + grid(0).y, 0.5f - depth_bias, 1.0f));
  shadow_matrix_ = to_texture * cam.view_proj;
  const float filter_texels = static_cast<float>(n) + (cfg.shadow_filter == ShadowFilter::kPcf2x2);
  penumbra_mm_ = filter_texels * cam.texel_world / gs.scene().units_per_mm;

  depth_ = sim::RenderTarget("shadow_map", size, size, cfg.shadow_depth);
  const sim::Filter filter =
      cfg.shadow_filter == ShadowFilter::kNearest ? sim::Filter::kNearest : sim::Filter::kBilinear;
  texture_ = sim::texture_view(depth_, {filter, sim::Wrap::kClamp});

  auto vs = sim::make_vertex_program<shaders::ShadowVS>({cam.view_proj});
  sim::RenderPassDesc pass;
  pass.name = "shadow";
  pass.depth = &depth_;
  pass.store_depth = true;
  for (const GpuMesh& m : gs.meshes()) {
    sim::DrawCall d;
    d.geometry = m.geometry;
    d.vertex_program = vs;
    pass.draws.push_back(d);
  }
  passes.push_back(gpu.execute(pass));
}

shaders::LightVertexUniforms FrameLights::vertex_uniforms(Transmission transmission) const {
  shaders::LightVertexUniforms v;
  v.shadow_coord = shadows_;
  v.shadow_matrix = shadow_matrix_;
  v.shadow_normal_offset = normal_offset_;
  v.thickness = transmission == Transmission::kComputedHere && transmission_;
  return v;
}

void FrameLights::bind(sim::DrawCall& draw) const {
  if (shadows_) draw.textures.textures[shaders::LightBindings::kShadowMap] = &texture_;
}

}  // namespace skinsim::pipeline

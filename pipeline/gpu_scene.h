// A scene as GPU resources: textures with mip chains, the environment cube maps, and
// draw geometry per mesh. Built once per scene and shared by every pipeline run on it.
#pragma once

#include <deque>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "pipeline/bake/ray_scene.h"
#include "pipeline/config.h"
#include "scene/scene.h"
#include "sim/render_pass.h"
#include "sim/texture.h"

namespace skinsim::pipeline {

struct GpuMaterial {
  scene::MaterialKind kind = scene::MaterialKind::kOther;
  const sim::Texture2D* base_color = nullptr;  // RGB gamma-encoded albedo, A reflectivity
  const sim::Texture2D* normal = nullptr;      // tangent-space normal map
  glm::vec4 base_color_factor{1.0f};
  float reflectivity = 1.0f;
};

struct GpuMesh {
  const scene::Mesh* mesh = nullptr;
  int material = 0;
  sim::Geometry geometry;  // with the baked thickness as a vertex attribute
};

// Axis-aligned bounds in world space; empty when lo > hi.
struct Bounds {
  glm::vec3 lo{1e30f};
  glm::vec3 hi{-1e30f};
  bool empty() const { return lo.x > hi.x; }
  glm::vec3 centre() const { return empty() ? glm::vec3(0.0f) : 0.5f * (lo + hi); }
  void add(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

class GpuScene {
 public:
  explicit GpuScene(const scene::Scene& scene);
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  const scene::Scene& scene() const { return scene_; }
  const std::vector<GpuMaterial>& materials() const { return materials_; }
  const std::vector<GpuMesh>& meshes() const { return meshes_; }
  // Sharp environment (eye reflections) and a cosine-convolved one (skin rim light, sampled
  // with the vertex normal, GPU Pro 5).
  const sim::TextureCube& environment() const { return environment_; }
  const sim::TextureCube& environment_diffuse() const { return environment_diffuse_; }
  bool has_skin() const;
  const Bounds& bounds() const { return bounds_; }  // every mesh
  // The character: skin and eyes (every mesh when there are neither), what the shadow map
  // is fitted to.
  const Bounds& character_bounds() const { return character_bounds_; }
  const Bounds& skin_bounds() const { return skin_bounds_; }
  // Every mesh for ray casting (the reference's visibility; the thickness bake).
  const bake::RayScene& rays() const { return *rays_; }

 private:
  const sim::Texture2D* add_texture(sim::Texture2D texture);

  const scene::Scene& scene_;
  std::deque<sim::Texture2D> textures_;  // deque: stable addresses
  std::vector<GpuMaterial> materials_;
  std::vector<GpuMesh> meshes_;
  std::vector<std::vector<float>> thickness_mm_;  // per mesh, per vertex (offline bake)
  Bounds bounds_, character_bounds_, skin_bounds_;
  std::unique_ptr<bake::RayScene> rays_;
  sim::TextureCube environment_;
  sim::TextureCube environment_diffuse_;
};

// Camera matrices for a render resolution, and the skin's screen footprint.
struct View {
  glm::mat4 view_proj{1.0f};
  // Where shaders place the viewer: normalize(eye - p) is the view vector. Orthographic
  // views put it 1e4 view-volume sizes behind the camera (make_view), so that this same
  // expression gives the parallel view direction (to ~1e-4 rad) in every program and the
  // perspective programs stay as they are.
  glm::vec3 eye{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit view direction
  glm::vec3 camera_position{0.0f};       // the camera itself (the eye of perspective views)
  bool orthographic = false;
  int width = 0;
  int height = 0;
  // Perspective: pixels per unit of world size at distance 1. Orthographic: pixels per
  // unit of world size at any distance.
  float focal_pixels = 0.0f;
  float skin_distance = 0.0f;  // camera to the skin bounding-box centre (world units)
  sim::PixelRect skin_rect;    // screen bounding rectangle of all skin (pixels)
  bool skin_visible = false;
  // Pixels per world unit on a surface `distance` units from the camera.
  float pixels_per_unit(float distance) const {
    return orthographic ? focal_pixels : focal_pixels / distance;
  }
  // Unit vector from a surface point towards the viewer (parallel for orthographic views).
  glm::vec3 to_viewer(const glm::vec3& p) const {
    return orthographic ? -forward : glm::normalize(eye - p);
  }
  // Pixels per millimetre on the skin at its distance (drives the blur width).
  float pixels_per_mm(float units_per_mm) const {
    if (orthographic) return focal_pixels * units_per_mm;
    return skin_distance > 0.0f ? focal_pixels * units_per_mm / skin_distance : 0.0f;
  }
};

// The view of a frame: the scene's camera with the framing knobs (lighting.h), at the
// config's (resolved) resolution.
View make_view(const GpuScene& gpu_scene, const PipelineConfig& config);

}  // namespace skinsim::pipeline

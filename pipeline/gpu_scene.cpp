#include "pipeline/gpu_scene.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "pipeline/bake/thickness.h"
#include "pipeline/environment_filter.h"
#include "pipeline/lighting.h"

namespace skinsim::pipeline {

namespace {

sim::Texture2D image_texture(const scene::Image& image) {
  return sim::Texture2D(image.name, image.width, image.height, image.texels,
                        sim::TexelFormat::kRGBA8, {sim::Filter::kTrilinear, sim::Wrap::kRepeat},
                        true);
}

sim::Texture2D solid_texture(const std::string& name, glm::vec4 value) {
  return sim::Texture2D(name, 1, 1, {value}, sim::TexelFormat::kRGBA8,
                        {sim::Filter::kBilinear, sim::Wrap::kRepeat}, false);
}

}  // namespace

GpuScene::GpuScene(const scene::Scene& scene) : scene_(scene) {
  std::vector<const sim::Texture2D*> images;
  for (const scene::Image& image : scene.images)
    images.push_back(add_texture(image_texture(image)));
  const sim::Texture2D* white = add_texture(solid_texture("white", glm::vec4(1.0f)));
  const sim::Texture2D* flat = add_texture(solid_texture("flat_normal", {0.5f, 0.5f, 1.0f, 1.0f}));

  for (const scene::Material& m : scene.materials) {
    GpuMaterial g;
    g.kind = m.kind;
    g.base_color = m.base_color_texture >= 0 ? images.at(m.base_color_texture) : white;
    g.normal = m.normal_texture >= 0 ? images.at(m.normal_texture) : flat;
    g.base_color_factor = m.base_color_factor;
    g.reflectivity = m.reflectivity;
    materials_.push_back(g);
  }
  if (materials_.empty()) materials_.push_back({scene::MaterialKind::kOther, white, flat});

  std::vector<bake::RayMesh> ray_meshes;
  for (const scene::Mesh& mesh : scene.meshes) {
    ray_meshes.push_back({&mesh.positions, &mesh.indices});
    const scene::MaterialKind kind =
        materials_[static_cast<std::size_t>(std::max(mesh.material, 0))].kind;
    for (const glm::vec3& p : mesh.positions) {
      bounds_.add(p);
      if (kind != scene::MaterialKind::kOther) character_bounds_.add(p);
      if (kind == scene::MaterialKind::kSkin) skin_bounds_.add(p);
    }
  }
  if (character_bounds_.empty()) character_bounds_ = bounds_;
  rays_ = std::make_unique<bake::RayScene>(ray_meshes);
  thickness_mm_.reserve(scene.meshes.size());  // stable addresses for the attributes
  for (const scene::Mesh& mesh : scene.meshes) {
    thickness_mm_.push_back(
        bake::bake_thickness_mm(*rays_, mesh.positions, mesh.normals, scene.units_per_mm));
    GpuMesh g;
    g.mesh = &mesh;
    g.material = mesh.material >= 0 ? mesh.material : 0;
    g.geometry.attributes.positions = mesh.positions.data();
    g.geometry.attributes.normals = mesh.normals.empty() ? nullptr : mesh.normals.data();
    g.geometry.attributes.uvs = mesh.uvs.empty() ? nullptr : mesh.uvs.data();
    g.geometry.attributes.tangents = mesh.tangents.empty() ? nullptr : mesh.tangents.data();
    g.geometry.attributes.thickness = thickness_mm_.back().data();
    g.geometry.vertex_count = mesh.positions.size();
    g.geometry.indices = mesh.indices.data();
    g.geometry.index_count = mesh.indices.size();
    meshes_.push_back(g);
  }

  const scene::CubeMap& env = scene.environment;
  // Half-float cube maps (OES_texture_half_float, supported by SGX5xx) keep the HDR range.
  environment_ = sim::TextureCube("environment", env.size, env.faces, sim::TexelFormat::kRGBA16F,
                                  {sim::Filter::kTrilinear, sim::Wrap::kClamp}, true);
  const scene::CubeMap diffuse = cosine_filter(env, 16);
  environment_diffuse_ = sim::TextureCube("environment_diffuse", diffuse.size, diffuse.faces,
                                          sim::TexelFormat::kRGBA16F,
                                          {sim::Filter::kBilinear, sim::Wrap::kClamp}, false);
}

const sim::Texture2D* GpuScene::add_texture(sim::Texture2D texture) {
  textures_.push_back(std::move(texture));
  return &textures_.back();
}

bool GpuScene::has_skin() const {
  return std::any_of(meshes_.begin(), meshes_.end(), [&](const GpuMesh& m) {
    return materials_[m.material].kind == scene::MaterialKind::kSkin;
  });
}

View make_view(const GpuScene& gpu_scene, const PipelineConfig& config) {
  const scene::Camera cam = frame_camera(gpu_scene, config);
  const int width = config.width, height = config.height;
  View v;
  v.width = width;
  v.height = height;
  v.eye = cam.position;
  v.camera_position = cam.position;
  v.forward = glm::normalize(cam.target - cam.position);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  if (cam.projection == scene::Projection::kOrthographic) {
    // glTF: the viewport's aspect wins over xmag / ymag; ymag is kept.
    const float half_w = cam.ymag * aspect;
    const glm::mat4 proj = glm::ortho(-half_w, half_w, -cam.ymag, cam.ymag, cam.znear, cam.zfar);
    v.view_proj = proj * glm::lookAt(cam.position, cam.target, cam.up);
    v.orthographic = true;
    v.focal_pixels = 0.5f * static_cast<float>(height) / cam.ymag;
    v.eye = cam.position - v.forward * (1e4f * (cam.zfar + std::max(half_w, cam.ymag)));
  } else {
    const glm::mat4 proj = glm::perspective(cam.yfov_radians, aspect, cam.znear, cam.zfar);
    v.view_proj = proj * glm::lookAt(cam.position, cam.target, cam.up);
    v.focal_pixels = 0.5f * static_cast<float>(height) / std::tan(0.5f * cam.yfov_radians);
  }

  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  float x0 = static_cast<float>(width), y0 = static_cast<float>(height), x1 = 0.0f, y1 = 0.0f;
  for (const GpuMesh& m : gpu_scene.meshes()) {
    if (gpu_scene.materials()[m.material].kind != scene::MaterialKind::kSkin) continue;
    for (const glm::vec3& p : m.mesh->positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      const glm::vec4 c = v.view_proj * glm::vec4(p, 1.0f);
      // Behind a perspective camera: the skin may cover everything (orthographic w is 1).
      if (!v.orthographic && c.w <= cam.znear * 0.5f) {
        x0 = y0 = 0.0f;
        x1 = static_cast<float>(width);
        y1 = static_cast<float>(height);
        continue;
      }
      const float sx = (c.x / c.w * 0.5f + 0.5f) * width, sy = (0.5f - c.y / c.w * 0.5f) * height;
      x0 = std::min(x0, sx);
      y0 = std::min(y0, sy);
      x1 = std::max(x1, sx);
      y1 = std::max(y1, sy);
    }
  }
  if (lo.x <= hi.x) {
    v.skin_distance = glm::length(0.5f * (lo + hi) - cam.position);
    v.skin_rect.x0 = std::clamp(static_cast<int>(std::floor(x0)) - 1, 0, width);
    v.skin_rect.y0 = std::clamp(static_cast<int>(std::floor(y0)) - 1, 0, height);
    v.skin_rect.x1 = std::clamp(static_cast<int>(std::ceil(x1)) + 1, 0, width);
    v.skin_rect.y1 = std::clamp(static_cast<int>(std::ceil(y1)) + 1, 0, height);
    v.skin_visible = v.skin_rect.x1 > v.skin_rect.x0 && v.skin_rect.y1 > v.skin_rect.y0;
  }
  return v;
}

}  // namespace skinsim::pipeline

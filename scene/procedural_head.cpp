#include "scene/procedural_head.h"

#include <fmt/format.h>

#include <cmath>

#include "scene/error.h"
#include "scene/head_mesh.h"
#include "scene/head_shape.h"
#include "scene/skin_textures.h"
#include "scene/studio_lighting.h"
#include "scene/validate.h"

namespace skinsim::scene {
namespace {

void check_range(const char* field, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    throw SceneError(
        fmt::format("DefaultSceneOptions.{} must be in [{}, {}], got {}", field, lo, hi, value));
  }
}

Material make_material(const std::string& name, const std::string& kind,
                       const glm::vec3& linear_color, float roughness) {
  Material m;
  m.name = name;
  m.extras_kind = kind;
  m.base_color_factor = glm::vec4(linear_color, 1.0f);
  m.roughness_factor = roughness;
  return m;
}

// Close-up: the frame spans about 16 cm vertically at the face (forehead to chin), so the
// face covers most of a 4:3 frame.
Camera close_up_camera(float aspect) {
  Camera cam;
  cam.position = glm::vec3(0.0f, 0.0f, 0.55f);
  cam.target = glm::vec3(0.0f, -0.015f, 0.0f);
  const float face_distance = 0.55f - 0.08f;
  const float half_height = 0.5f * 0.16f * std::max(1.0f, (4.0f / 3.0f) / aspect);
  cam.yfov_radians = 2.0f * std::atan(half_height / face_distance);
  cam.znear = 0.05f;
  cam.zfar = 2.0f;
  return cam;
}

}  // namespace

Scene make_default_scene(const DefaultSceneOptions& o) {
  check_range("head_triangles", o.head_triangles, 1000, 4000000);
  check_range("texture_size", o.texture_size, 16, 8192);
  check_range("eye_texture_size", o.eye_texture_size, 8, 4096);
  check_range("environment_size", o.environment_size, 1, 4096);
  check_range("aspect", o.aspect, 0.1, 10.0);

  Scene s;
  s.source = "builtin:default-head";
  head::SkinTextures skin = head::paint_skin_textures(o.texture_size);
  s.images.push_back(std::move(skin.albedo_reflectivity));
  s.images.push_back(std::move(skin.normal));
  s.images.push_back(head::paint_eye_texture(o.eye_texture_size));

  // Skin: reflectivity comes from the albedo texture's alpha, so the factor stays 1.
  Material skin_mat = make_material("skin", "skin", glm::vec3(1.0f), 0.45f);
  skin_mat.base_color_texture = 0;
  skin_mat.normal_texture = 1;
  Material eye = make_material("eye", "eye", glm::vec3(1.0f), 0.1f);
  eye.base_color_texture = 2;
  s.materials = {skin_mat, eye,
                 make_material("shirt", "other", glm::vec3(0.02f, 0.03f, 0.07f), 0.8f),
                 make_material("backdrop", "other", glm::vec3(0.18f, 0.19f, 0.21f), 0.9f)};

  s.meshes.push_back(head::make_head_mesh(o.head_triangles));
  s.meshes.back().material = 0;
  const float r = head::eye_radius();
  s.meshes.push_back(
      head::make_ellipsoid("eye_left", head::eye_center(false), glm::vec3(r), 32, 24));
  s.meshes.push_back(
      head::make_ellipsoid("eye_right", head::eye_center(true), glm::vec3(r), 32, 24));
  s.meshes[1].material = s.meshes[2].material = 1;
  // Shoulders under the neck; the neck's bottom end is hidden inside.
  s.meshes.push_back(head::make_ellipsoid("shirt", glm::vec3(0.0f, -0.37f, -0.01f),
                                          glm::vec3(0.21f, 0.13f, 0.15f), 48, 32));
  s.meshes.back().material = 2;
  s.meshes.push_back(head::make_wall("backdrop", -0.4f, -1.0f, 1.0f, -1.0f, 1.0f));
  s.meshes.back().material = 3;

  s.camera = close_up_camera(o.aspect);
  s.key_light = default_key_light();
  s.back_light = default_back_light(s.key_light);
  s.ambient = default_ambient();
  s.environment = make_studio_environment(o.environment_size, s.key_light);
  s.units_per_mm = 0.001f;
  classify_materials(s, {});
  validate_scene(s);
  return s;
}

}  // namespace skinsim::scene

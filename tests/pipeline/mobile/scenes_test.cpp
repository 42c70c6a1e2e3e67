#include "scene/procedural_head.h"
#include "tests/pipeline/mobile/test_scenes.h"

namespace skinsim::pipeline::testing {

scene::Scene flat_skin_patch(float albedo, float ambient) {
  scene::Scene s;
  s.source = "test:flat-patch";
  scene::Material m;
  m.name = "skin";
  m.kind = scene::MaterialKind::kSkin;
  m.base_color_factor = glm::vec4(albedo, albedo, albedo, 1.0f);
  m.reflectivity = 1.0f;
  s.materials.push_back(m);
  scene::Mesh quad;
  quad.name = "patch";
  quad.material = 0;
  const float h = 0.1f;  // 20 cm square, metres
  quad.positions = {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.tangents.assign(4, glm::vec4(1, 0, 0, 1));
  quad.indices = {0, 1, 2, 0, 2, 3};
  s.meshes.push_back(quad);
  s.camera.position = {0, 0, 0.5f};
  s.camera.target = {0, 0, 0};
  s.camera.yfov_radians = 0.3f;  // the patch fills the frame
  s.camera.znear = 0.05f;
  s.camera.zfar = 10.0f;
  s.key_light.direction = {0, 0, 1};
  s.key_light.radiance = glm::vec3(1.0f);
  s.ambient = glm::vec3(ambient);
  s.environment.size = 4;
  for (auto& face : s.environment.faces) face.assign(16, glm::vec4(0.2f, 0.2f, 0.2f, 1.0f));
  s.units_per_mm = 0.001f;
  return s;
}

scene::Scene small_head() {
  scene::DefaultSceneOptions o;
  o.head_triangles = 6000;
  o.texture_size = 128;
  o.eye_texture_size = 64;
  o.environment_size = 16;
  return scene::make_default_scene(o);
}

}  // namespace skinsim::pipeline::testing

#include "driver/frame/scene_source.h"

#include <filesystem>

#include "io/read_file.h"
#include "scene/error.h"
#include "scene/gltf_input.h"
#include "scene/gltf_loader.h"
#include "scene/procedural_head.h"
#include "util/fingerprint.h"

namespace skinsim::driver {

scene::Scene load_scene(const SceneSource& source, float aspect) {
  if (source.builtin()) {
    if (!source.skin_albedo.empty()) {
      throw scene::SceneError(
          "--skin-albedo: the built-in head has its own painted albedo (and reflectivity in its "
          "alpha); the option colours a scan's skin (--scene file.glb)");
    }
    scene::DefaultSceneOptions o;
    o.head_triangles = source.head_triangles;
    o.texture_size = source.texture_size;
    o.aspect = aspect;
    scene::Scene s = scene::make_default_scene(o);
    if (!source.skin_materials.empty()) scene::classify_materials(s, source.skin_materials);
    return s;
  }
  return scene::load_gltf(source.path, gltf_load_options(source, aspect));
}

scene::LoadOptions gltf_load_options(const SceneSource& source, float aspect) {
  scene::LoadOptions o;
  o.units_per_mm = source.units_per_mm;
  o.aspect = aspect;
  o.skin_materials = source.skin_materials;
  o.skin_albedo = source.skin_albedo;
  o.warn = source.warn;
  return o;
}

nlohmann::json scene_fingerprint(const SceneSource& scene) {
  nlohmann::json j = {{"label", scene.label()},
                      {"head_triangles", scene.head_triangles},
                      {"texture_size", scene.texture_size},
                      {"skin_materials", scene.skin_materials},
                      {"units_per_mm", scene.units_per_mm}};
  if (!scene.skin_albedo.empty()) {
    j["skin_albedo"] = scene.skin_albedo;
    // An image's content, so an edited texture at the same path is not taken for the old one.
    if (std::filesystem::is_regular_file(scene.skin_albedo)) {
      j["skin_albedo_content"] = content_fingerprint(
          io::read_regular_file(scene.skin_albedo, "--skin-albedo image", std::uintmax_t{1} << 30));
    }
  }
  // The built-in head is made by the code, which the build identity covers.
  if (!scene.builtin()) j["content"] = scene::gltf::content_fingerprint_of(scene.path);
  return j;
}

}  // namespace skinsim::driver

#include "driver/scene_source.h"

#include "scene/gltf_loader.h"
#include "scene/procedural_head.h"

namespace skinsim::driver {

scene::Scene load_scene(const SceneSource& source, float aspect) {
  if (source.builtin()) {
    scene::DefaultSceneOptions o;
    o.head_triangles = source.head_triangles;
    o.texture_size = source.texture_size;
    o.aspect = aspect;
    scene::Scene s = scene::make_default_scene(o);
    if (!source.skin_materials.empty()) scene::classify_materials(s, source.skin_materials);
    return s;
  }
  scene::LoadOptions o;
  o.units_per_mm = source.units_per_mm;
  o.aspect = aspect;
  o.skin_materials = source.skin_materials;
  o.warn = source.warn;
  return scene::load_gltf(source.path, o);
}

}  // namespace skinsim::driver

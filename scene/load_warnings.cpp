#include "scene/load_warnings.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>
#include <vector>

namespace skinsim::scene {

void warn_untextured_materials(const Scene& scene,
                               const std::function<void(const std::string&)>& warn,
                               bool include_skin) {
  std::set<int> used;
  for (const Mesh& m : scene.meshes) used.insert(m.material);
  std::vector<std::string> names;
  bool skin = false;
  for (int i : used) {
    const Material& m = scene.materials[static_cast<std::size_t>(i)];
    if (m.kind == MaterialKind::kSkin && !include_skin) continue;
    if (m.base_color_texture < 0 && m.normal_texture < 0 && m.metallic_roughness_texture < 0) {
      skin = skin || m.kind == MaterialKind::kSkin;
      names.push_back(
          fmt::format("'{}'", m.name.empty() ? fmt::format("materials[{}]", i) : m.name));
    }
  }
  if (names.empty()) return;
  warn(fmt::format(
      "{}: material{} {} ha{} no textures; drawn with neutral defaults (the flat base colour "
      "factor, no normal map, the roughness factor){}",
      scene.source, names.size() == 1 ? "" : "s", fmt::join(names, ", "),
      names.size() == 1 ? "s" : "ve",
      skin ? "; give skin a colour with --skin-albedo r,g,b (sRGB, e.g. 194,150,130, the "
             "ColorChecker's 'light skin' patch) or an image"
           : ""));
}

}  // namespace skinsim::scene

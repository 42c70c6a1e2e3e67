#include "scene/load_warnings.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>
#include <vector>

#include "scene/bounds.h"

namespace skinsim::scene {

void warn_implausible_head_size(const Scene& scene,
                                const std::function<void(const std::string&)>& warn) {
  Bounds skin;
  bool any = false;
  for (const Mesh& m : scene.meshes) {
    if (scene.materials[static_cast<std::size_t>(m.material)].kind != MaterialKind::kSkin) continue;
    skin.grow(mesh_bounds(m));
    any = true;
  }
  if (!any) return;
  const float height_units = skin.extent().y;
  const float height_mm = height_units / scene.units_per_mm;
  if (height_mm >= kPlausibleHeadMinMm && height_mm <= kPlausibleHeadMaxMm) return;
  warn(fmt::format(
      "{}: the skin meshes are {:.4g} units tall, {:.4g} mm at units_per_mm {:.4g}; a human "
      "head is about 200-250 mm, so diffusion widths will be off. If this is a life-size "
      "head, pass --units-per-mm {:.3g} (= {:.4g} units / {} mm)",
      scene.source, height_units, height_mm, scene.units_per_mm, height_units / kTypicalHeadMm,
      height_units, kTypicalHeadMm));
}

void warn_untextured_materials(const Scene& scene,
                               const std::function<void(const std::string&)>& warn) {
  std::set<int> used;
  for (const Mesh& m : scene.meshes) used.insert(m.material);
  std::vector<std::string> names;
  for (int i : used) {
    const Material& m = scene.materials[static_cast<std::size_t>(i)];
    if (m.base_color_texture < 0 && m.normal_texture < 0 && m.metallic_roughness_texture < 0) {
      names.push_back(
          fmt::format("'{}'", m.name.empty() ? fmt::format("materials[{}]", i) : m.name));
    }
  }
  if (names.empty()) return;
  warn(fmt::format(
      "{}: material{} {} ha{} no textures; drawn with neutral defaults (the flat base colour "
      "factor, no normal map, the roughness factor)",
      scene.source, names.size() == 1 ? "" : "s", fmt::join(names, ", "),
      names.size() == 1 ? "s" : "ve"));
}

}  // namespace skinsim::scene

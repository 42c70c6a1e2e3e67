#include "scene/sole_skin.h"

#include <fmt/format.h>

#include <algorithm>

#include "scene/head_measure.h"

namespace skinsim::scene {

std::string take_sole_material_as_skin(Scene& scene) {
  const auto is = [](MaterialKind kind) {
    return [kind](const Material& m) { return m.kind == kind; };
  };
  if (std::any_of(scene.materials.begin(), scene.materials.end(), is(MaterialKind::kSkin))) {
    return "";
  }
  const auto candidate = [](const Material& m) {
    return m.kind == MaterialKind::kOther && m.extras_kind.empty();
  };
  if (std::count_if(scene.materials.begin(), scene.materials.end(), candidate) != 1) return "";
  Material& sole = *std::find_if(scene.materials.begin(), scene.materials.end(), candidate);
  sole.kind = MaterialKind::kSkin;
  if (!measure_head(scene).head) {
    sole.kind = MaterialKind::kOther;
    return "";
  }
  return fmt::format(
      "material '{}' is taken as skin: no material is named skin, and it is the only one, "
      "shaped like a head (--skin-materials names the skin instead)",
      sole.name);
}

}  // namespace skinsim::scene

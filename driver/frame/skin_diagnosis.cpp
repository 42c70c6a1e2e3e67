#include "driver/frame/skin_diagnosis.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace skinsim::driver {

std::string no_skin_reason(const scene::Scene& scene,
                           const std::vector<std::string>& skin_materials) {
  std::vector<std::string> names, skin;
  for (const scene::Material& m : scene.materials) {
    names.push_back(m.name);
    if (m.kind == scene::MaterialKind::kSkin) skin.push_back(m.name);
  }
  const std::string listed =
      names.empty() ? "it has none" : fmt::format("its materials: {}", fmt::join(names, ", "));
  std::vector<std::string> unmatched;
  for (const std::string& wanted : skin_materials) {
    if (wanted != "all" && std::find(names.begin(), names.end(), wanted) == names.end()) {
      unmatched.push_back(wanted);
    }
  }
  if (!unmatched.empty()) {
    return fmt::format(
        "no skin in the frame: --skin-materials {} match no material of the scene ({}); pass "
        "the skin materials' names, or 'all'",
        fmt::join(unmatched, ", "), listed);
  }
  if (skin.empty()) {
    return fmt::format(
        "no skin in the frame: no material is skin by its extras.skinsim.kind or by a name "
        "containing \"skin\" ({}); pass --skin-materials with the skin materials' names, or "
        "'all'",
        listed);
  }
  return fmt::format(
      "no skin in the frame: the skin materials ({}) are not visible from the camera; check "
      "the scene's camera",
      fmt::join(skin, ", "));
}

}  // namespace skinsim::driver

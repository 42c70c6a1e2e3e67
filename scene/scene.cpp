#include "scene/scene.h"

#include <algorithm>

#include "util/text.h"

namespace skinsim::scene {

void classify_materials(Scene& scene, const std::vector<std::string>& skin_override) {
  const bool all_skin =
      std::find(skin_override.begin(), skin_override.end(), "all") != skin_override.end();
  for (Material& m : scene.materials) {
    const bool overridden =
        std::find(skin_override.begin(), skin_override.end(), m.name) != skin_override.end();
    const std::string name = lowercase(m.name);
    if (all_skin || overridden) {
      m.kind = MaterialKind::kSkin;
    } else if (m.extras_kind == "skin") {
      m.kind = MaterialKind::kSkin;
    } else if (m.extras_kind == "eye") {
      m.kind = MaterialKind::kEye;
    } else if (m.extras_kind == "other") {
      m.kind = MaterialKind::kOther;
    } else if (name.find("skin") != std::string::npos) {
      m.kind = MaterialKind::kSkin;
    } else if (name.find("eye") != std::string::npos) {
      m.kind = MaterialKind::kEye;
    } else {
      m.kind = MaterialKind::kOther;
    }
  }
}

}  // namespace skinsim::scene

// A bare head scan's one material is its skin. LeePerrySmith.glb's only material is called
// 'Material.002': the name rule (classify_materials) finds no skin in it, so without
// `--skin-materials` the scan rendered with the single-pass LOD shader and no skin metrics,
// and a new user had to find the option. The scan's shape settles it instead of its name.
#pragma once

#include <string>

#include "scene/scene.h"

namespace skinsim::scene {

// When no material is skin after classify_materials and exactly one is neither an eye nor
// marked "other" in its glTF extras, that material is tried as skin: it stays skin when its
// geometry shows a head (measure_head), and returns to other otherwise (a card, a prop).
// Returns what a user should be told when it was taken, else "". Call only when the user
// named no skin materials.
std::string take_sole_material_as_skin(Scene& scene);

}  // namespace skinsim::scene

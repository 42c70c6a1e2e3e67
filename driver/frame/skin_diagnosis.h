// Why a frame shows no skin, in the user's terms: which classification rule found nothing
// (scene::classify_materials) or that the skin is out of view, and what to pass instead.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace skinsim::driver {

// For a scene (classified with `skin_materials`, the --skin-materials names) whose reference
// frame has no skin pixel: names given that match no material (listing the scene's material
// names), else that neither extras.skinsim.kind nor a material name marks any material as skin,
// else that the skin materials exist but none is visible from the camera.
std::string no_skin_reason(const scene::Scene& scene,
                           const std::vector<std::string>& skin_materials);

}  // namespace skinsim::driver

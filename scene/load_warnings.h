// Notices for a user bringing their own head scan: materials drawn with neutral defaults
// because they have no textures (its size: scene_scale.h).
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace skinsim::scene {

// Warns once, naming every material in use that has no texture at all (skin materials only
// when `include_skin`: not when --skin-albedo gave them their colour), and for skin suggests
// --skin-albedo.
void warn_untextured_materials(const Scene& scene,
                               const std::function<void(const std::string&)>& warn,
                               bool include_skin);

}  // namespace skinsim::scene

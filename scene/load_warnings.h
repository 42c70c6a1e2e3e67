// Notices for a user bringing their own head scan: plausibility of its size in the given
// units, and materials drawn with neutral defaults because they have no textures.
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace skinsim::scene {

// A head is about 200-250 mm tall; outside this range the units are almost surely wrong.
inline constexpr float kPlausibleHeadMinMm = 100.0f;
inline constexpr float kPlausibleHeadMaxMm = 400.0f;
inline constexpr float kTypicalHeadMm = 225.0f;

// Warns when the skin meshes' height (Y extent, glTF is Y-up) at scene.units_per_mm is
// outside [kPlausibleHeadMinMm, kPlausibleHeadMaxMm], suggesting a --units-per-mm value.
void warn_implausible_head_size(const Scene& scene,
                                const std::function<void(const std::string&)>& warn);

// Warns once, naming every material in use that has no texture at all.
void warn_untextured_materials(const Scene& scene,
                               const std::function<void(const std::string&)>& warn);

}  // namespace skinsim::scene

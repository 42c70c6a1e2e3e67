// False-colour rendering of per-pixel error maps for writing and viewing.
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "image/image.h"

namespace skinsim::quality {

enum class ColorMap { kMagma, kViridis };

// The colour map at t (clamped to [0,1]), as sRGB-encoded display values.
glm::vec3 color_map(ColorMap map, float t);

// One pixel per map value, value clamped to [0,1]; a NaN value is drawn as the map's 0.
image::Image false_colour(const image::ScalarMap& map, ColorMap colors = ColorMap::kMagma);

}  // namespace skinsim::quality

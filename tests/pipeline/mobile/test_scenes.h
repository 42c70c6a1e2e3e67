// Small scenes for pipeline tests.
#pragma once

#include "scene/scene.h"

namespace skinsim::pipeline::testing {

// A flat square of skin facing the camera (+Z), uniform albedo, flat normal map, lit head-on
// by the key light, constant environment: where no approximation of the pipeline matters.
scene::Scene flat_skin_patch(float albedo, float ambient);

// The built-in head, small and fast: few triangles, small textures.
scene::Scene small_head();

}  // namespace skinsim::pipeline::testing

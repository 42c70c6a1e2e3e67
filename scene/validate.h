// Consistency checks every loader runs on the scene it produces, so that consumers can
// index without checking: attribute arrays of equal length, indices in range, finite
// positions, material/texture references in range, images with width*height texels.
#pragma once

#include "scene/scene.h"

namespace skinsim::scene {

// Throws SceneError("<scene.source>: <mesh/field>: <what is wrong>") on the first problem.
void validate_scene(const Scene& scene);

}  // namespace skinsim::scene

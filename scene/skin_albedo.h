// --skin-albedo: the colour of skin for a scan that has none of its own (LeePerrySmith.glb's
// only material is a flat lavender), given as an sRGB colour "r,g,b" (0-255 each, e.g.
// 194,150,130: the ColorChecker's "light skin" patch) or an image file (PNG, JPEG...; sRGB
// colour, read with the skin meshes' TEXCOORD_0 as a glTF baseColorTexture would be).
#pragma once

#include <string>

#include "scene/scene.h"

namespace skinsim::scene {

// Makes `spec` the base colour of every skin material: a colour becomes the linear base
// colour factor with no texture; an image becomes the base colour texture (sRGB) with a
// factor of 1. Alpha, metallic, roughness, normal maps and reflectivity are kept. Throws
// SceneError naming --skin-albedo for a malformed colour, an unreadable image, or a scene with
// no skin material.
void apply_skin_albedo(Scene& scene, const std::string& spec);

}  // namespace skinsim::scene

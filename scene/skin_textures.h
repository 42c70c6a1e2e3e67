// Procedural textures of the built-in head, painted over head_shape's (u, v) so they line
// up with the mesh: skin albedo + reflectivity, a tangent-space normal map with pores and
// wrinkles, and the eyes' albedo. Deterministic (hash noise, fixed seeds).
#pragma once

#include "scene/scene.h"

namespace skinsim::scene::head {

struct SkinTextures {
  // RGB: skin albedo, sRGB-encoded, with blotchy variation, redder lips and cheeks, darker
  // brows. A: specular reflectivity in [0, 1] (linear), higher on the oily T-zone.
  Image albedo_reflectivity;
  // Tangent-space normal, encoded n * 0.5 + 0.5, linear; +X along +u, +Y towards the top
  // of the image (glTF / MikkTSpace convention, see mesh_attributes.h).
  Image normal;
};

// Both images are size x size.
SkinTextures paint_skin_textures(int size);

// Eye albedo for make_ellipsoid's UVs (v = 0 at the front pole): pupil, iris with radial
// streaks and a dark limbal ring, sclera with faint veins. sRGB; A = reflectivity.
Image paint_eye_texture(int size);

}  // namespace skinsim::scene::head

// The lighting every scene gets unless its file says otherwise: a key light from the
// upper front left, a little ambient, and a procedural photo-studio environment cube map
// (gradient walls, a bright softbox behind the key light, a dimmer rim box behind right).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace skinsim::scene {

// Key light from the upper front left of a subject that faces +Z (viewer on +Z, looking
// at -Z, so "left" in the picture is -X).
DirectionalLight default_key_light();
glm::vec3 default_ambient();
// The studio's rim box axis for a key light: behind the subject on the side opposite the
// key, slightly above. The back light shines from there.
glm::vec3 rim_axis(const DirectionalLight& key);
DirectionalLight default_back_light(const DirectionalLight& key);

// World direction (not normalised) through texel position (s, t) in [-1, 1]^2 of cube face
// `face` (+X, -X, +Y, -Y, +Z, -Z), OpenGL convention (GL 4.6 spec, table 8.19): s grows
// to the right, t grows downwards (row 0 at the top).
glm::vec3 cube_face_direction(int face, float s, float t);

// Linear HDR radiance, `face_size` texels per edge; the main softbox sits around `key`'s
// direction so reflections agree with the key light. Deterministic.
CubeMap make_studio_environment(int face_size, const DirectionalLight& key);

}  // namespace skinsim::scene

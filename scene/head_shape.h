// The analytic shape of the built-in head (metres, +Y up, the face looks along +Z): a
// surface parametrised by texture coordinates, so the mesh (head_mesh.h) and the
// textures (skin_textures.h) sample the same function and always line up.
//
// u in [0, 1] goes once around the vertical axis with the seam at the back (u = 0.5 is the
// front centre line, u grows towards +X); v in [0, 1] runs from the crown (v = 0) over the
// face and under the chin down to the bottom of the neck (v = 1). Cylindrical unwrap.
#pragma once

#include <glm/glm.hpp>

namespace skinsim::scene::head {

// Where the skin surface is at (u, v).
glm::vec3 surface_point(float u, float v);

// Centre and radius of the left (-X) and right (+X) eyeballs, seated in the eye sockets.
glm::vec3 eye_center(bool right);
float eye_radius();

// Bottom of the neck (y) and the neck's centre line (z), for closing the mesh.
float neck_bottom_y();
float neck_center_z();

// Soft region masks in [0, 1] at a surface point, for the texture painters.
struct Regions {
  float lips = 0.0f;
  float brows = 0.0f;
  float t_zone = 0.0f;  // forehead, nose, chin: oilier, more reflective
  float cheeks = 0.0f;
  float eye_lids = 0.0f;  // skin around the eye sockets
  float forehead = 0.0f;  // where horizontal wrinkles go
  float crow_feet = 0.0f;
  float nasolabial = 0.0f;
};
Regions regions_at(const glm::vec3& p);

}  // namespace skinsim::scene::head

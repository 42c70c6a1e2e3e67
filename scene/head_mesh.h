// Tessellation of the built-in scene's geometry: the head (head_shape.h), eyeballs, a
// shirt and a backdrop. All meshes come with smooth normals, UVs and tangents.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "scene/scene.h"

namespace skinsim::scene::head {

// Closed head-and-neck mesh with about `target_triangles` triangles (within 1%): a
// columns x rows grid over head_shape's (u, v), a fan at the crown and a cap under the neck.
// Seam vertices are duplicated for the UVs; normals are welded across the seam.
Mesh make_head_mesh(int target_triangles);

// Closed ellipsoid with its poles on the Z axis (so a sphere's +Z pole, v = 0, is the
// front: the iris of an eye), `slices` around and `stacks` from pole to pole.
Mesh make_ellipsoid(const std::string& name, const glm::vec3& center, const glm::vec3& radii,
                    int slices, int stacks);

// A rectangle facing +Z at depth z, spanning [x0, x1] x [y0, y1] (two triangles).
Mesh make_wall(const std::string& name, float z, float x0, float x1, float y0, float y1);

}  // namespace skinsim::scene::head

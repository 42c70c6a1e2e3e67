// Where the reference's shadow rays start: on the smooth surface the vertex normals describe,
// not on the flat triangle. A flat triangle of a curved mesh lies below that surface, so near
// the terminator (N.L small but positive for the interpolated normal) a ray leaving the
// triangle towards the light meets the neighbouring triangles: a hard, faceted self-shadow
// that follows triangle edges (the "shadow terminator problem"). Hanika's fix (Hacking the
// Shadow Terminator, Ray Tracing Gems II, ch. 4, 2021; Blender Cycles' shadow terminator
// geometry offset) lifts the ray's origin onto that surface.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "pipeline/gpu_scene.h"

namespace skinsim::pipeline::reference {

// Hanika's point for the point with `barycentric` weights on a triangle of `corners` with
// unit vertex `normals`: each corner's tangent plane lifts the point where it lies below it
// (convex parts; concave ones stay on the triangle), and the lifted points are blended by the
// same weights.
glm::vec3 smooth_surface_point(const std::array<glm::vec3, 3>& corners,
                               const std::array<glm::vec3, 3>& normals,
                               const glm::vec3& barycentric);

// smooth_surface_point() of the triangle seen at `p` (a G-buffer position) from `eye`: the
// triangle is found by a ray along the view direction through p, from `slack` before it to
// `slack` behind it. p itself when no triangle is there or its mesh has no normals.
glm::vec3 shadow_ray_origin(const GpuScene& gs, const glm::vec3& eye, const glm::vec3& p,
                            float slack);

}  // namespace skinsim::pipeline::reference

// Derives missing per-vertex attributes of a triangle mesh: smooth normals and tangents.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace skinsim::scene {

// Smooth, area-weighted vertex normals: each triangle adds its unnormalised face normal
// (|cross| = 2 * area) to its vertices. Vertices at bit-identical positions are welded for
// the sum, so UV seams (split vertices) do not show as creases. A vertex that no
// non-degenerate triangle touches gets +Z.
std::vector<glm::vec3> compute_smooth_normals(const std::vector<glm::vec3>& positions,
                                              const std::vector<std::uint32_t>& indices);

// Per-vertex tangents in the MikkTSpace convention as glTF uses it: T follows +u, the
// bitangent B = cross(N, T.xyz) * T.w follows "up" in the image, i.e. -v of glTF's
// top-left-origin UVs (MikkTSpace runs on bottom-left-origin UVs, v' = 1 - v).
//
// Simplified against full MikkTSpace (Mikkelsen 2008, mikktspace.c): per-triangle
// tangent/bitangent from UV derivatives, weighted by triangle area (MikkTSpace weights by
// the corner angle and splits vertices whose triangles disagree in handedness or that sit
// on hard edges; this does not split vertices, so a vertex shared by mirrored UV islands
// gets the majority handedness). Then Gram-Schmidt against N and w = sign(dot(cross(N, T),
// B)). Triangles with degenerate UVs contribute nothing; a vertex left without a tangent
// gets any unit vector orthogonal to N, w = +1.
std::vector<glm::vec4> compute_tangents(const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs,
                                        const std::vector<std::uint32_t>& indices);

// A unit vector orthogonal to the unit vector n (Frisvad-style branchless basis, Duff et
// al. 2017, "Building an Orthonormal Basis, Revisited").
glm::vec3 any_orthogonal(const glm::vec3& n);

}  // namespace skinsim::scene

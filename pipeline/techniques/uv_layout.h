// What the techniques that work in the skin's UV layout (texture-space diffusion, the
// baked curvature of pre-integrated skin) need to know about it. They assume the skin
// meshes' UVs do not overlap (true of the built-in head and LeePerrySmith): overlapping
// islands would share texels.
#pragma once

#include <functional>
#include <vector>

#include "pipeline/gpu_scene.h"
#include "sim/texture.h"

namespace skinsim::pipeline {

// Throws ConfigError naming the technique and mesh when a skin mesh has no TEXCOORD_0.
void require_skin_uvs(const GpuScene& scene, const char* technique);

// Texels per millimetre of skin in a size x size UV-space texture, averaged over all skin
// triangles (sqrt of UV area over surface area). A stretch map would make it per texel.
float uv_texels_per_mm(const GpuScene& scene, int size);

// Curvature 1/r in 1/mm at each vertex of a mesh: the mean over its edges of
// |n_i - n_j| / |p_i - p_j| (the discrete form of length(dN) / length(dP)), then
// `smoothing_passes` of neighbour averaging (Penner & Borshukov bake it smoothed).
std::vector<float> vertex_curvature(const scene::Mesh& mesh, float units_per_mm,
                                    int smoothing_passes);

// Per-vertex values of the skin meshes rasterised into their UV layout (size x size, RGBA8,
// R = value / full_scale, at most 1), dilated by two texels so bilinear reads at island edges
// stay on the island's values. An offline bake.
using VertexValues = std::function<std::vector<float>(const scene::Mesh&)>;
sim::Texture2D vertex_value_texture(const GpuScene& scene, const char* name, int size,
                                    const VertexValues& values, float full_scale = 1.0f);

// The skin meshes' smoothed vertex curvature rasterised into their UV layout (size x size,
// RGBA8, R = curvature / max_curvature_per_mm clamped to 1), dilated by two texels so
// bilinear reads at island edges stay on the island's values. An offline bake.
sim::Texture2D curvature_texture(const GpuScene& scene, int size, float max_curvature_per_mm);

}  // namespace skinsim::pipeline

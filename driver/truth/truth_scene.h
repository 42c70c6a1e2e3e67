// `skinsim truth`, part 1: the scene skinsim renders, written for an independent path tracer
// (Blender Cycles, scripts/truth/cycles_render.py): the world-space triangles every pipeline
// and the reference rasterise, the frame's camera and lights (the knobs applied, as
// pipeline/lighting.h makes them), the materials, and the skin's diffusion profile as
// Cycles' random-walk subsurface radius. What each value means in Cycles, and what cannot be
// matched, is in docs/validation.md.
//
// Files written into a directory:
//   scene.json   camera, lights, world, materials, meshes (offsets into meshes.bin)
//   meshes.bin   per mesh, little-endian: float32 positions (3n), normals (3n), UVs (2n,
//                (0,0) = the image's top-left), then uint32 indices (3t)
//   textures/    base-colour images as RGBA PNGs (alpha: the reflectivity map)
#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "pipeline/config.h"
#include "pipeline/gpu_scene.h"

namespace skinsim::driver {

struct TruthSettings {
  int samples = 64;      // Cycles samples per pixel
  int max_bounces = 12;  // Cycles' total bounce limit (its default)
};

// Writes the three parts above into `dir` (created) and returns scene.json's content.
nlohmann::json write_truth_scene(const pipeline::GpuScene& scene,
                                 const pipeline::PipelineConfig& config,
                                 const TruthSettings& settings, const std::filesystem::path& dir);

// Cycles' random-walk "Subsurface Radius" per channel, mm, for the reference's profile.
// Cycles reads it as the diffusion length 1 / sigma_tr (its random walk takes the mean free
// path as radius * sqrt(3 (1 - alpha')), alpha' from the albedo): for the dipole that is
// Jensen's 1 / sigma_tr itself; the six Gaussians have no sigma_tr, so theirs is the dipole's
// scaled by the ratio of the two profiles' mean exit distances (docs/validation.md).
glm::vec3 subsurface_radius_mm(pipeline::ReferenceProfile profile);

// Mean distance from the point of entry at which a profile's light leaves, mm, per channel.
glm::vec3 mean_exit_distance_mm(pipeline::ReferenceProfile profile);

}  // namespace skinsim::driver

// Loads a glTF 2.0 file (.gltf with external/embedded buffers, or .glb) into a Scene.
//
// What is read: the default scene's node tree (TRS or matrix transforms, applied so meshes
// are in world space); triangle primitives (TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN;
// POINTS/LINES primitives are skipped with a warning) with POSITION, NORMAL, TEXCOORD_0,
// TANGENT; materials (base colour factor/texture, normal texture + scale, metallic-
// roughness factors/texture, KHR_materials_specular specularFactor as reflectivity,
// extras.skinsim.kind); the images those materials use, decoded to RGBA; the first
// perspective camera in the node tree; the first KHR_lights_punctual directional light.
//
// What is made up when missing: smooth normals (glTF asks for flat normals; a head scan
// without normals is meant to be smooth), MikkTSpace-style tangents (mesh_attributes.h),
// planar UVs from the primitive's x/y extent, a camera framing the scene from +Z (glTF
// assets face +Z), the default key light + ambient, and always the studio environment
// (studio_lighting.h).
//
// Every error throws SceneError with a message that starts with the file path.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace skinsim::scene {

struct LoadOptions {
  // World units per millimetre; <= 0 means glTF's metres (0.001). Scans exported in other
  // units (LeePerrySmith.glb is about 8 units tall) need this set for correct diffusion widths.
  float units_per_mm = 0.0f;
  // Frame aspect (width / height) and vertical field of view for the auto-framed camera.
  float aspect = 4.0f / 3.0f;
  float auto_camera_yfov_radians = 0.5f;
  int environment_size = 64;
  // Passed to classify_materials() (the CLI's --skin-materials).
  std::vector<std::string> skin_materials;
  // Receives non-fatal problems (skipped primitives, ignored lights...). Empty: stderr.
  std::function<void(const std::string&)> warn;
};

Scene load_gltf(const std::string& path, const LoadOptions& opts);

}  // namespace skinsim::scene

// Loads a glTF 2.0 file (.gltf with external/embedded buffers, or .glb) into a Scene.
//
// What is read: the default scene's node tree (TRS or matrix transforms, applied so meshes
// are in world space); triangle primitives (TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN;
// POINTS/LINES primitives are skipped with a warning) with POSITION, NORMAL, TEXCOORD_0,
// TANGENT, morphed by their targets' weights (gltf_primitive.h); materials (base colour
// factor/texture, normal texture + scale, metallic-roughness factors/texture,
// KHR_materials_specular specularFactor as reflectivity,
// extras.skinsim.kind; occlusionTexture and the specular extension's textures are named in
// a warning and not read); the images those materials use, decoded to RGBA; the first
// perspective camera in the node tree; the first KHR_lights_punctual directional light.
//
// What is made up when missing: smooth normals (glTF asks for flat normals; a head scan
// without normals is meant to be smooth), MikkTSpace-style tangents (mesh_attributes.h),
// planar UVs from the primitive's x/y extent, a camera framing the head (head_measure.h),
// else the scene, from +Z (glTF assets face +Z), the scale (scene_scale.h), the default key light +
// ambient, and always the studio environment (studio_lighting.h).
//
// Every error throws SceneError with a message that starts with the file path.
#pragma once

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace skinsim::scene {

struct NodeAnimation;

struct LoadOptions {
  // World units per millimetre; <= 0: glTF's metres when they give a head of plausible size,
  // else sized from the head itself (scene_scale.h; LeePerrySmith.glb's head is about 4.4
  // units from crown to chin).
  float units_per_mm = 0.0f;
  // Frame aspect (width / height) and vertical field of view for the auto-framed camera.
  float aspect = 4.0f / 3.0f;
  float auto_camera_yfov_radians = 0.5f;
  int environment_size = 64;
  // Passed to classify_materials() (the CLI's --skin-materials).
  std::vector<std::string> skin_materials;
  // The CLI's --skin-albedo (skin_albedo.h): empty keeps the file's base colours.
  std::string skin_albedo;
  // Receives non-fatal problems (skipped primitives, ignored lights...). Empty: stderr.
  std::function<void(const std::string&)> warn;
};

Scene load_gltf(const std::string& path, const LoadOptions& opts);

// A glTF file read once (parsed, its materials' images decoded) and posed any number of times:
// each pose is the scene load_gltf makes, with the nodes an animation moves at a time
// (gltf_animation.h), so a sequence does not parse and decode the file again for every frame.
// A warning is passed on once, not again for every pose that raises it.
class PosedGltf {
 public:
  PosedGltf(const std::string& path, const LoadOptions& opts);
  PosedGltf(const PosedGltf&) = delete;  // its warn refers to warned_
  PosedGltf& operator=(const PosedGltf&) = delete;
  ~PosedGltf();
  // Without `animation`, the file as it is (load_gltf).
  Scene pose(const NodeAnimation* animation, double time_s);

 private:
  std::string path_;
  LoadOptions opts_;
  std::unique_ptr<tinygltf::Model> model_;
  int scene_index_ = 0;
  Scene materials_;  // the file's materials and images, copied into every pose
  std::set<std::string> warned_;
};

}  // namespace skinsim::scene

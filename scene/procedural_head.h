// The built-in default scene, generated without any files: a dense head with skin
// textures, two eyes, a shirt and a backdrop, a key light + ambient, the studio
// environment, and a close-up camera in which skin fills most of a 4:3 frame.
// Metres (units_per_mm = 0.001). Deterministic; well under a second in Release.
#pragma once

#include "scene/scene.h"

namespace skinsim::scene {

struct DefaultSceneOptions {
  int head_triangles = 60000;  // head + neck mesh, within 1%
  int texture_size = 1024;     // skin albedo/reflectivity and normal map edge
  int eye_texture_size = 256;
  int environment_size = 64;   // cube map face edge
  float aspect = 4.0f / 3.0f;  // frame width / height the camera is set up for
};

// Materials: "skin" (kSkin; albedo+reflectivity texture, normal map), "eye" (kEye),
// "shirt" and "backdrop" (kOther). Throws SceneError on out-of-range options.
Scene make_default_scene(const DefaultSceneOptions& o);

}  // namespace skinsim::scene

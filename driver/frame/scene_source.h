// Where a run's scene comes from: the built-in procedural head, or a glTF file.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace skinsim::scene {
struct LoadOptions;
}

namespace skinsim::driver {

// The largest scene scale a user may give (units per millimetre): a nanometre-unit scene; any
// more is a typo, and 1e308 would overflow the float it is stored in.
constexpr double kMaxUnitsPerMm = 1e6;

struct SceneSource {
  std::string path;  // empty or "builtin" = the built-in default scene
  int head_triangles = 60000;
  int texture_size = 1024;
  std::vector<std::string> skin_materials;  // --skin-materials override
  float units_per_mm = 0.0f;  // <= 0: the file's metres if plausible, else from the head
  std::string skin_albedo;    // --skin-albedo (scene/skin_albedo.h); empty: the file's colours
  // Receives the loader's warnings (scene::LoadOptions::warn); empty: printed to stderr.
  std::function<void(const std::string&)> warn;
  bool builtin() const { return path.empty() || path == "builtin"; }
  std::string label() const { return builtin() ? "builtin:default-head" : path; }
};

// Loads or generates the scene; throws scene::SceneError naming the file on bad input.
scene::Scene load_scene(const SceneSource& source, float aspect);
// The glTF loader's options for a file `source` at a frame aspect.
scene::LoadOptions gltf_load_options(const SceneSource& source, float aspect);

// The scene a result depends on: the options (label, head triangles, texture size, skin
// materials, units per mm, skin albedo and an albedo image's content) and, for a glTF file, its
// content (scene::gltf:: content_fingerprint_of: the file and the buffers and images it names), so
// an edited scan at the same path is not mistaken for the old one. Part of a sweep configuration's
// fingerprint and of a kept reference's (reference_cache.h). Throws scene::SceneError as loading
// the file would.
nlohmann::json scene_fingerprint(const SceneSource& scene);

}  // namespace skinsim::driver

// Where a run's scene comes from: the built-in procedural head, or a glTF file.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace skinsim::driver {

struct SceneSource {
  std::string path;  // empty or "builtin" = the built-in default scene
  int head_triangles = 60000;
  int texture_size = 1024;
  std::vector<std::string> skin_materials;  // --skin-materials override
  float units_per_mm = 0.0f;                // <= 0: the file's own (glTF: metres)
  bool builtin() const { return path.empty() || path == "builtin"; }
  std::string label() const { return builtin() ? "builtin:default-head" : path; }
};

// Loads or generates the scene; throws scene::SceneError naming the file on bad input.
scene::Scene load_scene(const SceneSource& source, float aspect);

}  // namespace skinsim::driver

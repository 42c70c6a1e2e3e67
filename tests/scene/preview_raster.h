// A tiny reference z-buffer rasterizer for the scene tests and the preview tool: it shows
// what a camera sees (material per pixel) and a Lambert-shaded picture with the normal
// map applied. Test support only; the real renderer is sim/.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace skinsim::scene::testing {

struct PreviewFrame {
  int width = 0;
  int height = 0;
  std::vector<int> material;     // -1 = nothing drawn
  std::vector<glm::vec3> color;  // linear RGB
};

// Rasterizes every mesh (back faces culled, counter-clockwise front) from scene.camera.
PreviewFrame rasterize(const Scene& scene, int width, int height);

// Fraction of pixels showing a material of the given kind.
double coverage(const Scene& scene, const PreviewFrame& f, MaterialKind kind);

}  // namespace skinsim::scene::testing

// Geometry for full-screen (or sub-rectangle) passes: a clip-space quad over a pixel
// rectangle of a w x h target with matching texture coordinates, and a pass drawing it.
#pragma once

#include <string>
#include <vector>

#include "sim/gpu.h"
#include "sim/mesh.h"
#include "sim/render_pass.h"

namespace skinsim::pipeline {

class ScreenQuad {
 public:
  ScreenQuad(const sim::PixelRect& rect, int width, int height);
  sim::Geometry geometry() const { return mesh_.geometry(); }

 private:
  sim::Mesh mesh_{{}, {}, {0, 1, 2, 0, 2, 3}};
};

// A quad pass (no culling, no depth) named `name` drawing one draw over `rect`.
sim::PassCounters quad_pass(const std::string& name, sim::DrawCall draw, sim::RenderTarget& target,
                            const sim::PixelRect& rect, sim::Gpu& gpu);

}  // namespace skinsim::pipeline

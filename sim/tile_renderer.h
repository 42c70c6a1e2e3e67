// The per-tile renderer (3D): for one tile, depth-tests every triangle of its list in
// on-chip tile memory, shades only the visible fragment of each pixel for opaque draws
// (deferred hidden-surface removal), shades blended draws in order, and resolves the tile
// to the render target. Its texture samples record their cache lines in the tile's
// TextureLineLog, which the tile's emulated core replays through its cache in tile order.
#pragma once

#include <vector>

#include "sim/binner.h"
#include "sim/counters.h"
#include "sim/geometry.h"
#include "sim/render_pass.h"
#include "sim/shader_io.h"
#include "sim/texture_unit.h"

namespace skinsim::sim {

class TileRenderer {
 public:
  TileRenderer(const RenderPassDesc& pass, const SetupTriangles& setup, const TileGrid& grid,
               const GpuConfig& config);

  // Renders tile (tx, ty) with the given triangle list; fills `counters` (all but the
  // cache's misses) and `lines` (emptied first).
  void render(int tx, int ty, const std::vector<std::uint32_t>& triangles, TileCounters& counters,
              TextureLineLog& lines);

 private:
  // Shades every tagged pixel; returns whether there was any.
  bool flush_tags(TileCounters& counters, std::vector<std::uint64_t>& shaded_by_draw);
  // A visible fragment waiting in a batch: its triangle, pixel and index in the tile.
  struct Waiting {
    std::uint32_t triangle;
    int px, py;
    std::size_t index;
  };
  // Shades batch_'s fragments (1 to 4, of one draw) together, blending them into the
  // tile by the draw's blend mode, and empties it.
  void shade_batch();

  const RenderPassDesc& pass_;
  const SetupTriangles& setup_;
  const TileGrid& grid_;
  const GpuConfig& config_;
  ExecTexUnit tex_;
  Exec4TexUnit tex4_;
  glm::vec2 inv_size_;
  PixelRect rect_{};
  std::vector<glm::vec4> color_;
  std::vector<float> depth_;
  std::vector<std::uint32_t> tag_;  // visible triangle + 1 per pixel, 0 = none
  std::vector<Waiting> batch_;      // visible fragments waiting to be shaded
};

}  // namespace skinsim::sim

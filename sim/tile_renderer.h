// The per-tile renderer (3D): for one tile, depth-tests every triangle of its list in
// on-chip tile memory (per sample under MSAA), shades only the visible fragments of each
// pixel for opaque draws (deferred hidden-surface removal), shades blended draws in order,
// and resolves the tile to the render target. Its texture samples record their cache lines in the
// tile's TextureLineLog, which the tile's emulated core replays through its cache in tile order.
#pragma once

#include <vector>

#include "sim/binner.h"
#include "sim/counters.h"
#include "sim/geometry.h"
#include "sim/render_pass.h"
#include "sim/sample_pattern.h"
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
  // Depth-tests (per sample), tags or shades one triangle's fragments in the tile; counts
  // those that pass the depth test in submission order per draw in `early_z`.
  template <int kSamples>
  void draw_triangle(std::uint32_t tri, TileCounters& counters, std::vector<std::uint64_t>& shaded,
                     std::vector<std::uint64_t>& early_z);
  // A visible fragment waiting in a batch: its triangle, pixel, the pixel's index in the
  // tile, and the samples (bit mask) its colour goes to.
  struct Waiting {
    std::uint32_t triangle;
    int px, py;
    std::size_t index;
    unsigned samples;
  };
  // Adds a fragment to the batch, shading the batch once it is full.
  void queue(std::uint32_t triangle, int px, int py, std::size_t index, unsigned samples);
  // Shades batch_'s fragments (1 to 4, of one draw) together, blending them into the
  // tile by the draw's blend mode, and empties it.
  void shade_batch();

  const RenderPassDesc& pass_;
  const SetupTriangles& setup_;
  const TileGrid& grid_;
  const GpuConfig& config_;
  const SamplePattern& pattern_;
  ExecTexUnit tex_;
  Exec4TexUnit tex4_;
  glm::vec2 inv_size_;
  PixelRect rect_{};
  // Tile memory, pattern_.count samples per pixel, a pixel's samples adjacent.
  std::vector<glm::vec4> color_;
  std::vector<float> depth_;
  std::vector<std::uint32_t> tag_;   // visible triangle + 1 per sample, 0 = none
  std::vector<glm::vec4> resolved_;  // one row of the tile, box-averaged (MSAA only)
  std::vector<Waiting> batch_;       // visible fragments waiting to be shaded
};

}  // namespace skinsim::sim

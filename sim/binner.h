// The tiler's back half: each set-up triangle goes into the list of every tile it touches
// (an exact edge test against the tile rectangle, not just its bounding box), and each
// tile's coverage is classified (llvmpipe lp_setup_tri.c does the same for its bins).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/counters.h"
#include "sim/geometry.h"

namespace skinsim::sim {

struct TileGrid {
  int tile_size = 32;
  int tiles_x = 0;
  int tiles_y = 0;
  PixelRect area;  // tile-aligned render area
  int width = 0;   // target size
  int height = 0;
  std::int64_t sample_reach = 0;  // SamplePattern::reach of the pass
  // Pixel rectangle of tile (tx, ty), clipped to the target.
  PixelRect tile_rect(int tx, int ty) const;
  bool in_area(int tx, int ty) const;
};

struct TileBins {
  std::vector<std::vector<std::uint32_t>> lists;  // per tile, triangle indices ascending
  std::vector<TileCoverage> coverage;
};

TileBins bin_triangles(const SetupTriangles& setup, const TileGrid& grid, PassCounters& counters);

}  // namespace skinsim::sim

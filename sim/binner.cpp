#include "sim/binner.h"

#include <algorithm>

namespace skinsim::sim {

PixelRect TileGrid::tile_rect(int tx, int ty) const {
  return {tx * tile_size, ty * tile_size, std::min((tx + 1) * tile_size, width),
          std::min((ty + 1) * tile_size, height)};
}

bool TileGrid::in_area(int tx, int ty) const {
  const PixelRect r = tile_rect(tx, ty);
  return r.x0 >= area.x0 && r.x1 <= area.x1 && r.y0 >= area.y0 && r.y1 <= area.y1;
}

namespace {

// Smallest and largest value of an edge function over the samples of a rectangle's pixels
// (bounded by their centres widened by the sample pattern's reach).
void edge_range(const TriangleSetup& t, int e, const PixelRect& r, std::int64_t reach,
                std::int64_t& lo, std::int64_t& hi) {
  const std::int64_t half = kSubpixelOne / 2;
  const std::int64_t x0 = r.x0 * kSubpixelOne + half - reach;
  const std::int64_t x1 = (r.x1 - 1) * kSubpixelOne + half + reach;
  const std::int64_t y0 = r.y0 * kSubpixelOne + half - reach;
  const std::int64_t y1 = (r.y1 - 1) * kSubpixelOne + half + reach;
  const std::int64_t ax_lo = std::min(t.edge_a[e] * x0, t.edge_a[e] * x1);
  const std::int64_t ax_hi = std::max(t.edge_a[e] * x0, t.edge_a[e] * x1);
  const std::int64_t by_lo = std::min(t.edge_b[e] * y0, t.edge_b[e] * y1);
  const std::int64_t by_hi = std::max(t.edge_b[e] * y0, t.edge_b[e] * y1);
  lo = ax_lo + by_lo + t.edge_c[e];
  hi = ax_hi + by_hi + t.edge_c[e];
}

}  // namespace

TileBins bin_triangles(const SetupTriangles& setup, const TileGrid& grid, PassCounters& counters) {
  TileBins bins;
  const size_t tile_count = static_cast<size_t>(grid.tiles_x) * grid.tiles_y;
  bins.lists.resize(tile_count);
  bins.coverage.assign(tile_count, TileCoverage::kEmpty);
  for (std::uint32_t i = 0; i < setup.triangles.size(); ++i) {
    const TriangleSetup& t = setup.triangles[i];
    const int tx0 = t.min_x / grid.tile_size, tx1 = t.max_x / grid.tile_size;
    const int ty0 = t.min_y / grid.tile_size, ty1 = t.max_y / grid.tile_size;
    for (int ty = ty0; ty <= ty1; ++ty) {
      for (int tx = tx0; tx <= tx1; ++tx) {
        const PixelRect r = grid.tile_rect(tx, ty);
        bool touches = true, covers = true;
        for (int e = 0; e < 3 && touches; ++e) {
          std::int64_t lo, hi;
          edge_range(t, e, r, grid.sample_reach, lo, hi);
          touches = hi >= 0;
          covers = covers && lo >= 0;
        }
        if (!touches) continue;
        const size_t index = static_cast<size_t>(ty) * grid.tiles_x + tx;
        bins.lists[index].push_back(i);
        if (covers) {
          bins.coverage[index] = TileCoverage::kFull;
        } else if (bins.coverage[index] == TileCoverage::kEmpty) {
          bins.coverage[index] = TileCoverage::kPartial;
        }
      }
    }
  }
  for (size_t i = 0; i < tile_count; ++i) {
    if (!grid.in_area(static_cast<int>(i % grid.tiles_x), static_cast<int>(i / grid.tiles_x))) {
      continue;
    }
    counters.tile_refs += bins.lists[i].size();
    switch (bins.coverage[i]) {
      case TileCoverage::kEmpty:
        ++counters.tiles_empty;
        break;
      case TileCoverage::kPartial:
        ++counters.tiles_partial;
        break;
      case TileCoverage::kFull:
        ++counters.tiles_full;
        break;
    }
  }
  return bins;
}

}  // namespace skinsim::sim

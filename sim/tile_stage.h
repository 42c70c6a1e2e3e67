// The 3D stage of a render: every tile of the render area shaded, resolved and counted, on
// the host threads of the calling task arena, with each emulated core's texture cache
// seeing its tiles' requests in tile order.
#pragma once

#include "sim/binner.h"
#include "sim/counters.h"
#include "sim/geometry.h"
#include "sim/render_pass.h"

namespace skinsim::sim {

// Fills c.tiles[i] (already laid out, with tile_x, tile_y and core) for every tile in the
// grid's render area.
void render_tiles(const RenderPassDesc& pass, const GpuConfig& config, const SetupTriangles& setup,
                  const TileGrid& grid, const TileBins& bins, PassCounters& c);

}  // namespace skinsim::sim

// Cost of one tile on a 3D core: depth test (ISP), shading (USSE), texturing (TMU), and the
// DRAM bytes the tile moves.
#pragma once

#include <vector>

#include "gpu_model/device_profile.h"
#include "gpu_model/timing.h"
#include "sim/counters.h"

namespace skinsim::gpu_model {

struct TileWork {
  double isp_cycles = 0.0;
  double alu_cycles = 0.0;
  double texture_cycles = 0.0;
  double overhead_cycles = 0.0;
  DramBytes dram;  // parameter_write stays 0

  // ISP, USSE and TMU pipeline within a tile (a TBDR streams depth-tested fragments into the
  // USSE, whose texture requests go to the TMUs), so the tile takes as long as its busiest
  // unit, assuming perfect overlap, plus a fixed per-tile cost.
  double cycles() const;
  Unit bottleneck() const;
};

// Passes over its pixels that a tile of `pass` takes to fit its MSAA samples in tile
// memory: ceil(tile pixels x samples x PassCounters::tile_bytes_per_sample / tile memory).
// `tile_memory_bytes` <= 0: the device states none, and its tile memory is taken to hold
// the profile's tile at one sample per pixel, so each doubling of samples halves the tile,
// as PowerVR does (32x32 -> 32x16 -> 16x16 pixels: Imagination, PowerVR Performance
// Recommendations, "MSAA Performance"). 1 for any 1x pass.
int msaa_tile_passes(const sim::PassCounters& pass, double tile_memory_bytes);

// A tile with no work and no traffic lies outside the render area and costs nothing.
// `fragment_cycles` holds, per draw of the pass, one fragment's issue cycles on one pipe.
TileWork estimate_tile(const sim::TileCounters& tile, const sim::PassCounters& pass,
                       const std::vector<double>& fragment_cycles, const DeviceProfile& profile);

}  // namespace skinsim::gpu_model

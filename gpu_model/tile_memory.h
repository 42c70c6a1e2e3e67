// The tile a GPU renders when its pixels are large: tile memory holds a fixed number of bytes,
// so a G-buffer (or MSAA samples) beyond it shrinks the tile (Arm GPU Best Practices: 256
// bits per pixel at 16x16 on Valhall; Apple imageblocks 32x32, 32x16, 16x16 in 32 KiB;
// Adreno bins sized to GMEM).
#pragma once

#include "gpu_model/device_profile.h"

namespace skinsim::gpu_model {

struct TileShape {
  int width = 0;
  int height = 0;
};

// Largest tile, halving the profile's tile (height first, as 32x32 -> 32x16 -> 16x16), whose
// pixels fit tile.memory_bytes at `colour_bytes_per_pixel` (all render targets, times the
// samples). Binning GPUs keep depth/stencil in GMEM too, so their pixels also hold
// tile.depth_stencil_bytes_per_pixel. Never below 1x1.
TileShape fitted_tile(const DeviceProfile& profile, double colour_bytes_per_pixel);

}  // namespace skinsim::gpu_model

#include "gpu_model/tile_memory.h"

namespace skinsim::gpu_model {

TileShape fitted_tile(const DeviceProfile& p, double colour_bytes_per_pixel) {
  double bytes_per_pixel = colour_bytes_per_pixel;
  if (p.gpu_class == GpuClass::kBinning) {
    bytes_per_pixel += p.tile_depth_stencil_bytes_per_pixel.value;
  }
  TileShape t{static_cast<int>(p.tile_width.value), static_cast<int>(p.tile_height.value)};
  const auto fits = [&] {
    return static_cast<double>(t.width) * t.height * bytes_per_pixel <= p.tile_memory_bytes.value;
  };
  while (!fits() && t.width * t.height > 1) {
    if (t.height >= t.width && t.height > 1) {
      t.height /= 2;
    } else {
      t.width /= 2;
    }
  }
  return t;
}

}  // namespace skinsim::gpu_model

#include "gpu_model/gpu_config.h"

#include <fmt/format.h>

#include "gpu_model/error.h"

namespace skinsim::gpu_model {

sim::GpuConfig gpu_config(const DeviceProfile& profile, int threads) {
  const SimParameters s = sim_parameters(profile);
  if (s.tile_width != s.tile_height) {
    throw ProfileError(fmt::format(
        "{}: fields 'tile.width' ({}) and 'tile.height' ({}) differ; the emulator renders "
        "square tiles",
        profile.source_path, s.tile_width, s.tile_height));
  }
  sim::GpuConfig c;
  c.tile_size = s.tile_width;
  c.cores = s.cores;
  c.texture_cache.size_bytes = static_cast<std::uint32_t>(s.texture_cache_bytes);
  c.texture_cache.line_bytes = static_cast<std::uint32_t>(s.texture_cache_line_bytes);
  c.texture_cache.associativity = static_cast<std::uint32_t>(s.texture_cache_ways);
  c.texture_cache.set_index =
      s.texture_cache_set_hash ? sim::SetIndex::kXorFold : sim::SetIndex::kModulo;
  c.depth_stencil_bytes_per_pixel = s.tile_depth_stencil_bytes_per_pixel;
  c.threads = threads;
  return c;
}

}  // namespace skinsim::gpu_model

#include "gpu_model/counter_checks.h"

#include <fmt/format.h>

#include "gpu_model/error.h"

namespace skinsim::gpu_model {
namespace {

void require_equal(const sim::PassCounters& pass, const char* field, std::uint64_t tiles_sum,
                   std::uint64_t total) {
  if (tiles_sum != total) {
    throw CounterError(fmt::format("pass '{}': {} is {} but the tiles sum to {}", pass.name, field,
                                   total, tiles_sum));
  }
}

}  // namespace

void check_counters(const sim::PassCounters& pass, const DeviceProfile& profile) {
  const auto fail = [&](const std::string& what) {
    throw CounterError(fmt::format("pass '{}': {}", pass.name, what));
  };
  if (pass.tile_size != static_cast<int>(profile.tile_width.value) ||
      pass.tile_size != static_cast<int>(profile.tile_height.value)) {
    fail(fmt::format("tile_size {} differs from profile '{}' tile {}x{}", pass.tile_size,
                     profile.name, profile.tile_width.value, profile.tile_height.value));
  }
  if (pass.cores != static_cast<int>(profile.cores.value)) {
    fail(
        fmt::format("cores {} differs from profile '{}' gpu.cores {} (texture-cache counts "
                    "depend on it: re-run the emulator with the profile)",
                    pass.cores, profile.name, profile.cores.value));
  }
  if (pass.tiles_x < 0 || pass.tiles_y < 0 ||
      pass.tiles.size() != static_cast<std::size_t>(pass.tiles_x) * pass.tiles_y) {
    fail(fmt::format("tiles has {} entries, expected tiles_x * tiles_y = {} * {}",
                     pass.tiles.size(), pass.tiles_x, pass.tiles_y));
  }
  for (std::size_t d = 0; d < pass.draws.size(); ++d) {
    for (const sim::OpProfile* ops :
         {&pass.draws[d].vertex_profile, &pass.draws[d].fragment_profile}) {
      if (ops->vector_ops_mediump > ops->vector_ops || ops->scalar_ops_mediump > ops->scalar_ops ||
          ops->transcendental_ops_mediump > ops->transcendental_ops) {
        fail(fmt::format("draws[{}] ({}): more mediump ops than ops of a class", d,
                         ops == &pass.draws[d].vertex_profile ? pass.draws[d].vertex_program
                                                              : pass.draws[d].fragment_program));
      }
    }
  }
  std::uint64_t refs = 0, texture = 0, color_load = 0, color_store = 0, depth_load = 0,
                depth_store = 0;
  for (std::size_t i = 0; i < pass.tiles.size(); ++i) {
    const sim::TileCounters& t = pass.tiles[i];
    for (const sim::DrawFragments& df : t.shaded_by_draw) {
      if (df.draw >= pass.draws.size()) {
        fail(
            fmt::format("tiles[{}] ({}, {}).shaded_by_draw refers to draw {} but the pass has "
                        "{} draws",
                        i, t.tile_x, t.tile_y, df.draw, pass.draws.size()));
      }
    }
    refs += t.triangle_refs;
    texture += t.texture.dram_bytes;
    color_load += t.color_load_bytes;
    color_store += t.color_store_bytes;
    depth_load += t.depth_load_bytes;
    depth_store += t.depth_store_bytes;
  }
  require_equal(pass, "tile_refs", refs, pass.tile_refs);
  require_equal(pass, "texture.dram_bytes", texture, pass.texture.dram_bytes);
  require_equal(pass, "color_load_bytes", color_load, pass.color_load_bytes);
  require_equal(pass, "color_store_bytes", color_store, pass.color_store_bytes);
  require_equal(pass, "depth_load_bytes", depth_load, pass.depth_load_bytes);
  require_equal(pass, "depth_store_bytes", depth_store, pass.depth_store_bytes);
}

}  // namespace skinsim::gpu_model

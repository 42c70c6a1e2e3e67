// Shared helpers of the cost-model tests: the shipped iPad 4 profile with round numbers, and
// synthetic pass counters.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "gpu_model/device_profile.h"
#include "gpu_model/error.h"
#include "gpu_model/profile_loader.h"
#include "sim/counters.h"
#include "tests/test_paths.h"

namespace skinsim::gpu_model::testing {

inline const std::string kDataDir = test_paths::kDataDir;

// The text of a shipped profile, data/devices/<name>.toml.
inline std::string shipped_text(const std::string& name) {
  std::ifstream in(kDataDir + "/devices/" + name + ".toml");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Parses `text` and returns the error message (empty when it parsed).
inline std::string parse_error(const std::string& text) {
  try {
    parse_device_profile(text, "edited.toml");
  } catch (const ProfileError& e) {
    return e.what();
  }
  return "";
}

// iPad 4 profile with a 100 MHz clock so expected times are easy to compute by hand.
inline DeviceProfile round_profile() {
  DeviceProfile p = load_device_profile("ipad4", kDataDir);
  p.clock_mhz.value = 100.0;  // 1e5 cycles per ms
  return p;
}

// An empty pass: tiles_x x tiles_y tiles of 32 px on `cores` cores.
inline sim::PassCounters make_pass(int tiles_x, int tiles_y, int cores) {
  sim::PassCounters pass;
  pass.name = "synthetic";
  pass.tile_size = 32;
  pass.tiles_x = tiles_x;
  pass.tiles_y = tiles_y;
  pass.width = 32 * tiles_x;
  pass.height = 32 * tiles_y;
  pass.cores = cores;
  for (int y = 0; y < tiles_y; ++y) {
    for (int x = 0; x < tiles_x; ++x) {
      sim::TileCounters t;
      t.tile_x = static_cast<std::uint16_t>(x);
      t.tile_y = static_cast<std::uint16_t>(y);
      pass.tiles.push_back(t);
    }
  }
  return pass;
}

// Adds a draw whose fragment program costs `vector_ops` vector instructions.
inline std::uint32_t add_draw(sim::PassCounters& pass, std::uint32_t vector_ops) {
  sim::DrawCounters d;
  d.fragment_program = "synthetic";
  d.fragment_profile.vector_ops = vector_ops;
  pass.draws.push_back(d);
  return static_cast<std::uint32_t>(pass.draws.size() - 1);
}

// Shades `fragments` opaque fragments of `draw` in `tile`.
inline void shade(sim::PassCounters& pass, std::size_t tile, std::uint32_t draw,
                  std::uint64_t fragments) {
  sim::TileCounters& t = pass.tiles[tile];
  t.shaded_by_draw.push_back({draw, fragments});
  t.fragments_shaded += fragments;
  t.fragments_depth_tested += fragments;
  pass.draws[draw].fragments_shaded += fragments;
}

// Recomputes the pass totals that must equal the sum over tiles.
inline void sum_tiles(sim::PassCounters& pass) {
  pass.tile_refs = 0;
  pass.fragments_depth_tested = pass.fragments_shaded = pass.fragments_blended = 0;
  pass.texture = {};
  pass.color_load_bytes = pass.color_store_bytes = 0;
  pass.depth_load_bytes = pass.depth_store_bytes = 0;
  for (const sim::TileCounters& t : pass.tiles) {
    pass.tile_refs += t.triangle_refs;
    pass.fragments_depth_tested += t.fragments_depth_tested;
    pass.fragments_shaded += t.fragments_shaded;
    pass.fragments_blended += t.fragments_blended;
    pass.texture.add(t.texture);
    pass.color_load_bytes += t.color_load_bytes;
    pass.color_store_bytes += t.color_store_bytes;
    pass.depth_load_bytes += t.depth_load_bytes;
    pass.depth_store_bytes += t.depth_store_bytes;
  }
}

}  // namespace skinsim::gpu_model::testing

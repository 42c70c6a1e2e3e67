#include "gpu_model/finite_timing.h"

#include <cmath>

#include "util/check.h"

namespace skinsim::gpu_model {
namespace {

void check_finite(const DramBytes& d) {
  SKINSIM_CHECK(std::isfinite(d.parameter_write) && std::isfinite(d.parameter_read) &&
                std::isfinite(d.texture) && std::isfinite(d.color_load) &&
                std::isfinite(d.color_store) && std::isfinite(d.depth_load) &&
                std::isfinite(d.depth_store) && std::isfinite(d.total()));
}

}  // namespace

void check_finite(const PassTiming& t) {
  SKINSIM_CHECK(std::isfinite(t.ta.vertex_cycles) && std::isfinite(t.ta.setup_cycles) &&
                std::isfinite(t.ta.binning_cycles) && std::isfinite(t.ta.bandwidth_ms) &&
                std::isfinite(t.ta.ms));
  SKINSIM_CHECK(std::isfinite(t.ta_ms) && std::isfinite(t.makespan_ms) &&
                std::isfinite(t.render_bandwidth_ms) && std::isfinite(t.render_ms) &&
                std::isfinite(t.standalone_ms) && std::isfinite(t.balance));
  for (int u = 0; u < kUnitCount; ++u) {
    SKINSIM_CHECK(std::isfinite(t.busy_ms[u]) && std::isfinite(t.utilisation[u]));
  }
  check_finite(t.dram);
  for (double busy : t.core_busy_ms) SKINSIM_CHECK(std::isfinite(busy));
  for (const TileTiming& tile : t.tiles) {
    SKINSIM_CHECK(std::isfinite(tile.start_ms) && std::isfinite(tile.ms) &&
                  std::isfinite(tile.isp_cycles) && std::isfinite(tile.alu_cycles) &&
                  std::isfinite(tile.texture_cycles) && std::isfinite(tile.overhead_cycles));
  }
}

void check_finite(const FrameTiming& f) {
  for (const PassSlot& s : f.schedule) {
    SKINSIM_CHECK(std::isfinite(s.ta_start_ms) && std::isfinite(s.ta_end_ms) &&
                  std::isfinite(s.render_start_ms) && std::isfinite(s.render_end_ms) &&
                  std::isfinite(s.exposed_ms));
  }
  check_finite(f.dram);
  SKINSIM_CHECK(std::isfinite(f.pipeline_ms) && std::isfinite(f.bandwidth_ms) &&
                std::isfinite(f.frame_ms) && std::isfinite(f.fps) && std::isfinite(f.dram_bytes) &&
                std::isfinite(f.dram_wait_ms));
}

}  // namespace skinsim::gpu_model

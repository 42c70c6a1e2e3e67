#include "gpu_model/pass_cost.h"

#include <algorithm>

#include "gpu_model/counter_checks.h"
#include "gpu_model/finite_timing.h"
#include "gpu_model/model_terms.h"
#include "gpu_model/tile_cost.h"
#include "gpu_model/tile_schedule.h"
#include "gpu_model/tiler_cost.h"

namespace skinsim::gpu_model {

PassTiming estimate_pass(const sim::PassCounters& pass, const DeviceProfile& p) {
  check_counters(pass, p);
  PassTiming t;
  t.name = pass.name;
  t.ta = estimate_tiler(pass, p);
  t.ta_ms = t.ta.ms;

  std::vector<double> fragment_cycles;
  fragment_cycles.reserve(pass.draws.size());
  for (const sim::DrawCounters& draw : pass.draws) {
    fragment_cycles.push_back(shader_cycles(draw.fragment_profile, p));
  }

  std::vector<TileWork> work;
  std::vector<double> durations;
  work.reserve(pass.tiles.size());
  durations.reserve(pass.tiles.size());
  for (const sim::TileCounters& tile : pass.tiles) {
    work.push_back(estimate_tile(tile, pass, fragment_cycles, p));
    durations.push_back(work.back().cycles());
  }
  const int cores = static_cast<int>(p.cores.value);
  const TileSchedule schedule = list_schedule(durations, cores);

  const double cpm = cycles_per_ms(p);
  const double bpm = dram_bytes_per_ms(p);
  double isp = 0.0, alu = 0.0, texture = 0.0, overhead = 0.0;
  t.tiles.reserve(work.size());
  for (std::size_t i = 0; i < work.size(); ++i) {
    const TileWork& w = work[i];
    TileTiming tt;
    tt.tile_x = pass.tiles[i].tile_x;
    tt.tile_y = pass.tiles[i].tile_y;
    tt.core = schedule.core[i];
    tt.start_ms = schedule.start[i] / cpm;
    tt.ms = durations[i] / cpm;
    tt.bottleneck = w.bottleneck();
    tt.isp_cycles = w.isp_cycles;
    tt.alu_cycles = w.alu_cycles;
    tt.texture_cycles = w.texture_cycles;
    tt.overhead_cycles = w.overhead_cycles;
    t.tiles.push_back(tt);
    isp += w.isp_cycles;
    alu += w.alu_cycles;
    texture += w.texture_cycles;
    overhead += tt.overhead_cycles;
    t.dram.add(w.dram);
  }
  t.dram.parameter_write = parameter_write_bytes(pass, p);

  // Renderer: the slower of the tile schedule and its DRAM traffic at achievable bandwidth
  // (roofline: Williams et al. 2009), plus the fixed cost of a render.
  const double render_overhead_ms = p.render_overhead_cycles.value / cpm;
  t.makespan_ms = schedule.makespan / cpm;
  t.render_bandwidth_ms = t.dram.renderer() / bpm;
  t.render_ms = std::max(t.makespan_ms, t.render_bandwidth_ms) + render_overhead_ms;
  // On its own, a pass can be no faster than either stage, nor than all its bytes (TA and 3D
  // share the DRAM).
  const double all_bandwidth_ms = t.dram.total() / bpm;
  t.standalone_ms = std::max({t.ta_ms, t.render_ms, all_bandwidth_ms});

  for (double busy : schedule.core_busy) t.core_busy_ms.push_back(busy / cpm);
  double mean_busy = 0.0;
  for (double busy : t.core_busy_ms) mean_busy += busy / cores;
  t.balance = t.makespan_ms > 0.0 ? mean_busy / t.makespan_ms : 1.0;

  // Busy time per unit; per-core units are averaged over the cores.
  const double core_ms = cpm * cores;
  t.busy_ms[static_cast<int>(Unit::kAlu)] = alu / core_ms;
  t.busy_ms[static_cast<int>(Unit::kTexture)] = texture / core_ms;
  t.busy_ms[static_cast<int>(Unit::kIsp)] = isp / core_ms;
  t.busy_ms[static_cast<int>(Unit::kBandwidth)] = all_bandwidth_ms;
  t.busy_ms[static_cast<int>(Unit::kTiler)] = t.ta_ms;
  t.busy_ms[static_cast<int>(Unit::kOverhead)] = overhead / core_ms + render_overhead_ms;
  int most = 0;
  for (int u = 0; u < kUnitCount; ++u) {
    if (t.busy_ms[u] > t.busy_ms[most]) most = u;  // first unit wins ties
    t.utilisation[u] = t.standalone_ms > 0.0 ? t.busy_ms[u] / t.standalone_ms : 0.0;
  }
  t.bottleneck = static_cast<Unit>(most);
  check_finite(t);
  return t;
}

}  // namespace skinsim::gpu_model

#include "gpu_model/tiler_cost.h"

#include <algorithm>

#include "gpu_model/model_terms.h"

namespace skinsim::gpu_model {

double parameter_write_bytes(const sim::PassCounters& pass, const DeviceProfile& p) {
  // Binned geometry goes to DRAM (hardware.md, parameter buffer): vertex data, per-triangle
  // index data and one control-stream entry per tile reference. Every shaded vertex is counted
  // (the counters do not say which vertices belong only to culled triangles).
  const double varyings = static_cast<double>(pass.varying_floats_per_vertex);
  return static_cast<double>(pass.vertices_shaded) * pb_vertex_bytes(p, varyings) +
         static_cast<double>(pass.triangles_binned) * p.pb_bytes_per_triangle.value +
         static_cast<double>(pass.tile_refs) * p.pb_bytes_per_tile_ref.value;
}

TilerTiming estimate_tiler(const sim::PassCounters& pass, const DeviceProfile& p) {
  const double cores = p.cores.value;
  TilerTiming t;
  // Vertex programs run on the unified USSE pipes of all cores (USSE is unified: AnandTech).
  double vertex_pipe_cycles = 0.0;
  for (const sim::DrawCounters& draw : pass.draws) {
    vertex_pipe_cycles +=
        static_cast<double>(draw.vertices_shaded) * shader_cycles(draw.vertex_profile, p);
  }
  t.vertex_cycles = vertex_pipe_cycles / (cores * p.pipes_per_core.value);
  // Setup/cull of every submitted triangle at the tiler rate (AnandTech: ~35 MTri/s per
  // SGX543 core at 200 MHz), scaled over cores.
  t.setup_cycles =
      static_cast<double>(pass.triangles_in) / (p.tiler_triangles_per_clock_per_core.value * cores);
  // Binning writes one reference per (triangle, tile) pair (profile assumption).
  t.binning_cycles =
      static_cast<double>(pass.tile_refs) / (p.tiler_tile_refs_per_clock_per_core.value * cores);
  t.bandwidth_ms = parameter_write_bytes(pass, p) / dram_bytes_per_ms(p);
  // The TA is a pipeline (vertex -> setup -> bin -> write): its stages overlap, so the slowest
  // one sets the stage time.
  const double cycles = std::max({t.vertex_cycles, t.setup_cycles, t.binning_cycles});
  t.ms = std::max(cycles / cycles_per_ms(p), t.bandwidth_ms);
  return t;
}

}  // namespace skinsim::gpu_model

#include "gpu_model/model_terms.h"

#include <algorithm>

namespace skinsim::gpu_model {

double shader_cycles(const sim::OpProfile& ops, const DeviceProfile& p) {
  // Instruction count x issue cycles per class, as an offline shader compiler reports
  // cycles (PVRShaderEditor); texture instructions take an issue slot (Imagination forum).
  // Mediump vector and scalar ops issue at alu.mediump_op_cost times the highp cost; no
  // source gives SGX a separate FP16 rate for transcendentals, so they cost the same.
  const double mediump = p.mediump_op_cost.value;
  const auto at_precision = [mediump](std::uint32_t all, std::uint32_t at_mediump) {
    return (all - at_mediump) + mediump * at_mediump;
  };
  return at_precision(ops.vector_ops, ops.vector_ops_mediump) * p.vector_op_cycles.value +
         at_precision(ops.scalar_ops, ops.scalar_ops_mediump) * p.scalar_op_cycles.value +
         ops.transcendental_ops * p.transcendental_op_cycles.value +
         ops.texture_reads() * p.texture_issue_cycles.value;
}

double fragments_shaded_on(const sim::DrawFragments& f, const DeviceProfile& p) {
  const auto visible = static_cast<double>(f.fragments_shaded);
  // Counters built without the early-Z count (tests, older stores) have no overdraw to add.
  const double overdraw = std::max(0.0, static_cast<double>(f.fragments_early_z) - visible);
  // On a TBDR the figure is exactly 1, so this is `visible` to the bit.
  return visible + (1.0 - p.hsr_overdraw_removed.value) * overdraw;
}

double texture_ops(const sim::TextureCounters& tex, const DeviceProfile& p) {
  const auto nearest = static_cast<double>(tex.samples_by_filter[0]);
  const auto bilinear = static_cast<double>(tex.samples_by_filter[1]);
  const auto trilinear = static_cast<double>(tex.samples_by_filter[2]);
  const auto samples = static_cast<double>(tex.samples());
  // A TMU delivers one bilinear quad per clock; nearest takes the same slot, trilinear two
  // (two mip levels).
  double ops = nearest + bilinear + trilinear * p.trilinear_bilinear_ops.value;
  // Wide formats run at a fraction of the rate. The counters do not split wide samples by
  // filter, so wide samples are assumed to have the tile's average filter mix.
  if (samples > 0.0) {
    ops += static_cast<double>(tex.samples_wide_format) * (p.wide_format_bilinear_ops.value - 1.0) *
           (ops / samples);
  }
  return ops;
}

double compressed_target_bytes(std::uint64_t bytes, const DeviceProfile& p) {
  return static_cast<double>(bytes) * p.framebuffer_compression.value;
}

double cycles_per_ms(const DeviceProfile& p) {
  return p.clock_mhz.value * 1e3;
}

double dram_bytes_per_ms(const DeviceProfile& p) {
  // Peak GB/s x achievable fraction; 1 GB/s = 1e6 bytes per ms.
  return p.dram_peak_gb_per_s.value * p.dram_achievable_fraction.value * 1e6;
}

double pb_vertex_bytes(const DeviceProfile& p, double varying_floats) {
  // Position plus varyings, as the TA writes them to the parameter buffer.
  return p.pb_vertex_position_bytes.value + varying_floats * p.pb_bytes_per_varying_float.value;
}

}  // namespace skinsim::gpu_model
